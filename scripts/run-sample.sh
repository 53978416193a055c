#!/usr/bin/env bash
# The main job on a fresh Debian 12 machine: sets it up, builds the plugins, and runs the automatic
# pipeline (measure, segment, fit + snap with sharp edges, measure) on the bundled sample scan of the
# bracket (bench/data), printing the accuracy before and after and the segmentation score. The bundled
# data is committed: OpenCASCADE is not needed.
# Usage: scripts/run-sample.sh [--meshlab 2020.09|2025.07] [run_pipeline.py options, e.g. --samples 200000]
#   2020.09 (default): Debian's MeshLab and meshlabserver; build tree build/.
#   2025.07: MeshLab 2025.07 built from Debian's source (cached) and tools/meshlab_runner; build-2025/.
# The report also goes to <build tree>/sample-report.md.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"

generation=2020.09
if [ "${1:-}" = "--meshlab" ]; then
  generation=${2:?--meshlab needs 2020.09 or 2025.07}
  shift 2
fi
case "$generation" in
  2020.09) build=build; batch=build/meshlab-prefix/bin/meshlabserver; gui=build/meshlab-prefix/bin/meshlab ;;
  2025.07) build=build-2025; batch=build-2025/meshlab-prefix/meshlab_runner; gui=build-2025/meshlab-prefix/meshlab ;;
  *) echo "run-sample: --meshlab must be 2020.09 or 2025.07, not $generation" >&2; exit 2 ;;
esac

scripts/setup-debian.sh
[ "$generation" = 2025.07 ] && scripts/setup-meshlab-2025.sh

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DPRIMITIVE_EDIT_MESHLAB="$generation"
targets="filter_segment filter_primitive_fit filter_measure_accuracy edit_primitive"
[ "$generation" = 2025.07 ] && targets="$targets meshlab_runner"
# shellcheck disable=SC2086
cmake --build "$build" -j"$(nproc)" --target $targets

python3 bench/run_pipeline.py --meshlabserver "$batch" \
  --cache "$build/bench-cache" --report "$build/sample-report.md" "$@"

# A copy to edit by hand: MeshLab's Save and Export dialogs open in the folder of the opened file, which for
# the bundled sample is the source tree's bench/data.
mkdir -p "$build/sample"
cp bench/data/bracket_scan.ply "$build/sample/bracket_scan.ply"
echo "run-sample: to edit the scan by hand (Edit > Primitive Edit), open the copy: $gui $build/sample/bracket_scan.ply"
echo "run-sample: the automatic result (face quality = segment id): $build/bench-cache/runs/bracket_scan/segmented.ply"
