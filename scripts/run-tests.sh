#!/usr/bin/env bash
# Sets up a Debian 12 machine (packages, MeshLab source) and runs every test: unit tests, meshlabserver
# script tests and GUI tests in a Release build, then the unit tests again under ASan and UBSan.
# Usage: scripts/run-tests.sh            (build trees: build/ and build-sanitize/)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
jobs=$(nproc)

scripts/setup-debian.sh

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

# Sanitizers: common/ through the unit tests (the plugins run inside Debian's uninstrumented MeshLab).
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPRIMITIVE_EDIT_SANITIZE=ON \
      -DPRIMITIVE_EDIT_BUILD_PLUGINS=OFF -DPRIMITIVE_EDIT_BUILD_BENCH=OFF
cmake --build build-sanitize -j"$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure -j"$jobs"
