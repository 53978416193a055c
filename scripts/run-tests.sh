#!/usr/bin/env bash
# Sets up a Debian 12 machine (packages, MeshLab source) and runs every test:
#  1. Release build: unit tests, meshlabserver script tests and the GUI test (MeshLab under Xvfb);
#  2. the unit tests again under AddressSanitizer and UndefinedBehaviorSanitizer;
#  3. the libFuzzer target over common/ for 60 s (clang, ASan + UBSan).
# Usage: scripts/run-tests.sh            (build trees: build/, build-sanitize/, build-fuzz/)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
jobs=$(nproc)

scripts/setup-debian.sh

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPRIMITIVE_EDIT_BUILD_BENCH=OFF
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure

# The plugins run inside Debian's uninstrumented MeshLab: sanitizers cover common/ through the unit tests.
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE= -DCMAKE_CXX_FLAGS="-O1 -g1" -DPRIMITIVE_EDIT_SANITIZE=ON \
      -DPRIMITIVE_EDIT_BUILD_PLUGINS=OFF -DPRIMITIVE_EDIT_BUILD_BENCH=OFF
cmake --build build-sanitize -j"$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure -j"$jobs"

CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE= -DPRIMITIVE_EDIT_BUILD_FUZZ=ON \
      -DPRIMITIVE_EDIT_BUILD_PLUGINS=OFF -DPRIMITIVE_EDIT_BUILD_TESTS=OFF -DPRIMITIVE_EDIT_BUILD_BENCH=OFF
cmake --build build-fuzz -j"$jobs"
ctest --test-dir build-fuzz --output-on-failure
