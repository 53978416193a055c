#!/usr/bin/env bash
# Regenerates the bundled sample of the paper's experiment in bench/data/:
#   bracket_reference.ply   exact CAD bracket, tessellated; per-face quality = B-rep face index
#   bracket_reference.json  per B-rep face: type, exact parameters, area (see bench/bracket/README.md)
#   bracket_scan.ply        simulated CT scan, paper preset at a coarse voxel (about 150k faces)
#   bracket_scan_truth.txt  per scan face (in order), the B-rep face index nearest to it
# and prints the scan's accuracy as the paper measures it. Without OpenCASCADE (no make_bracket) the
# committed reference is kept and only the scan is regenerated.
# Usage: bench/bracket/make_data.sh [BUILD_DIR]   (default: build)
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$here/build}
bin=$build/bench/bracket
data=$here/bench/data
# The bundled scan: the paper preset (roughness, blur, noise, threshold) at a voxel giving about 150k faces.
voxel=0.34
seed=1

for p in simulate_ct_scan measure_scan; do
  [ -x "$bin/$p" ] || { echo "make_data: $bin/$p not built (cmake --build $build --target $p)" >&2; exit 1; }
done
mkdir -p "$data"
if [ -x "$bin/make_bracket" ]; then
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  "$bin/make_bracket" --out "$tmp"
  mv "$tmp/reference.ply" "$data/bracket_reference.ply"
  mv "$tmp/reference.json" "$data/bracket_reference.json"
elif [ ! -f "$data/bracket_reference.ply" ]; then
  echo "make_data: no make_bracket (OpenCASCADE) and no committed reference" >&2
  exit 1
fi
"$bin/simulate_ct_scan" --in "$data/bracket_reference.ply" --out "$data/bracket_scan.ply" \
  --truth "$data/bracket_scan_truth.txt" --preset paper --voxel "$voxel" --seed "$seed"
"$bin/measure_scan" "$data/bracket_scan.ply" "$data/bracket_reference.ply"
