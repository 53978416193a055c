#!/usr/bin/env bash
# Sets up a Debian 12 machine and runs every test, for both MeshLab generations:
#  1. MeshLab 2020.09 (Debian's package), Release: unit tests, layout check, meshlabserver script tests
#     and the GUI test under Xvfb;
#  2. MeshLab 2025.07 (built from Debian's source, cached outside the clone), Release: the same script
#     tests through tools/meshlab_runner, the GUI test and the layout check;
#  3. the unit tests again under AddressSanitizer and UndefinedBehaviorSanitizer;
#  4. the libFuzzer target over common/ for 60 s (clang, ASan + UBSan).
# Usage: scripts/run-tests.sh     (build trees: build/, build-2025/, build-sanitize/, build-fuzz/)
# PRIMITIVE_EDIT_CACHE_DIR: where MeshLab 2025.07 is built (default ~/.cache/primitive-edit).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
jobs=$(nproc)
stage() { echo "=== $1 ($(date -u +%H:%M:%S), $SECONDS s since start)"; }

stage "setup: Debian packages and MeshLab 2020.09's source"
scripts/setup-debian.sh
stage "setup: MeshLab 2025.07 from Debian's source (cached)"
scripts/setup-meshlab-2025.sh

stage "MeshLab 2020.09: build and test"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPRIMITIVE_EDIT_MESHLAB=2020.09 -DPRIMITIVE_EDIT_BUILD_BENCH=OFF
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

stage "MeshLab 2025.07: build and test"
cmake -S . -B build-2025 -DCMAKE_BUILD_TYPE=Release -DPRIMITIVE_EDIT_MESHLAB=2025.07 -DPRIMITIVE_EDIT_BUILD_BENCH=OFF
cmake --build build-2025 -j"$jobs"
ctest --test-dir build-2025 --output-on-failure -j"$jobs"

# The plugins run inside uninstrumented MeshLabs: sanitizers cover common/ through the unit tests. Debug with
# its flags set to -O1 -g1: asserts (Eigen's index checks among them) stay on, and an empty build type would be
# made Release (-O3 -DNDEBUG), which doubled this stage's compile time on CI's 2 cores.
stage "unit tests under ASan + UBSan"
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DPRIMITIVE_EDIT_SANITIZE=ON \
      -DPRIMITIVE_EDIT_BUILD_PLUGINS=OFF -DPRIMITIVE_EDIT_BUILD_BENCH=OFF
cmake --build build-sanitize -j"$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure -j"$jobs"

stage "fuzz"
# Release for NDEBUG; the targets set their own -O2 (fuzz/CMakeLists.txt).
CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DPRIMITIVE_EDIT_BUILD_FUZZ=ON \
      -DPRIMITIVE_EDIT_BUILD_PLUGINS=OFF -DPRIMITIVE_EDIT_BUILD_TESTS=OFF -DPRIMITIVE_EDIT_BUILD_BENCH=OFF
cmake --build build-fuzz -j"$jobs"
ctest --test-dir build-fuzz --output-on-failure -j"$jobs"
stage "all tests passed"
