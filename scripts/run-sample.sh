#!/usr/bin/env bash
# The main job on a fresh Debian 12 machine: sets it up (packages, MeshLab source), builds the plugins,
# and runs the automatic pipeline (measure, segment, fit + snap with sharp edges, measure) on the bundled
# sample scan of the bracket (bench/data), printing the accuracy before and after and the segmentation
# score. The bundled data is committed: OpenCASCADE is not needed.
# Usage: scripts/run-sample.sh [run_pipeline.py options, e.g. --samples 200000]
#        (build tree: build/; the report also goes to build/sample-report.md)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"

scripts/setup-debian.sh

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target filter_segment filter_primitive_fit filter_measure_accuracy edit_primitive

python3 bench/run_pipeline.py --meshlabserver build/meshlab-prefix/bin/meshlabserver \
  --cache build/bench-cache --report build/sample-report.md "$@"
