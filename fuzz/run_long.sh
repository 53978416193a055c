#!/bin/bash
# run_long.sh: the long fuzz run over the core's entry points (issue: at least 10^7 executions, clean).
#
# Runs each fast libFuzzer target (fuzz_fit, fuzz_relate, fuzz_snap, fuzz_segment: ASan + UBSan, built by
# scripts/run-tests.sh or as in fuzz/CMakeLists.txt) for a number of executions, JOBS targets at a time, each
# from its own corpus under OUT (kept, so that a second run goes on from where the first stopped), then
# prints a table of executions, seconds and executions a second per target and the total. Exits non-zero when
# a target found a crash, a leak, undefined behaviour or a broken invariant (its input is saved in OUT as
# <target>-crash-*, -leak-*, -timeout-* or -oom-*; replay it with `build-fuzz/fuzz/<target> FILE`). An
# interrupted target (kill -INT of its process) counts the executions it ran.
#
# Usage: fuzz/run_long.sh [--build DIR] [--out DIR] [--jobs N] [--scale S]
#   --build  the fuzz build tree (default build-fuzz)
#   --out    corpora, logs and crash inputs (default build-fuzz/long-run)
#   --jobs   targets run at once (default 2)
#   --scale  multiplies the executions per target (default 1: 10^7 in all; 0.01 for a quick try)
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-fuzz
out=
jobs=2
scale=1
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --scale) scale=$2; shift 2 ;;
    *) echo "usage: $0 [--build DIR] [--out DIR] [--jobs N] [--scale S]" >&2; exit 2 ;;
  esac
done
out=${out:-$build/long-run}
mkdir -p "$out"

# Executions per target, 10^7 in all at scale 1, shared by speed: segmentation runs at a tenth of the snap's
# rate (ASan + UBSan, 2 cores), so it gets fewer executions.
targets=(fuzz_fit fuzz_relate fuzz_snap fuzz_segment)
runs=(2500000 2500000 4000000 1000000)

for t in "${targets[@]}"; do
  [ -x "$build/fuzz/$t" ] || { echo "$build/fuzz/$t is missing: build the fuzz targets first (see fuzz/CMakeLists.txt)" >&2; exit 2; }
done

run_one() {
  local t=$1 n=$2
  mkdir -p "$out/corpus_$t"
  local start
  start=$(date +%s.%N)
  local status=0
  "$build/fuzz/$t" -runs="$n" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$out/$t-" "$out/corpus_$t" > "$out/$t.log" 2>&1 || status=$?
  awk -v end="$(date +%s.%N)" -v start="$start" 'BEGIN { print end - start }' > "$out/$t.seconds"
  # 72: libFuzzer's exit code when interrupted (Ctrl-C, kill -INT): the executions so far still count.
  [ "$status" = 72 ] && { echo "$t interrupted" >&2; return 0; }
  return $status
}

pids=()
names=()
for i in "${!targets[@]}"; do
  n=$(awk -v r="${runs[$i]}" -v s="$scale" 'BEGIN { printf "%d", r * s }')
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 1; done
  echo "$(date -u +%H:%M:%S) ${targets[$i]}: $n executions"
  run_one "${targets[$i]}" "$n" &
  pids+=($!)
  names+=("${targets[$i]}")
done

failed=0
for i in "${!pids[@]}"; do
  wait "${pids[$i]}" || { failed=1; echo "${names[$i]} FAILED: see $out/${names[$i]}.log" >&2; }
done

printf '%-14s %12s %9s %10s\n' target executions seconds "exec/s"
total=0
for t in "${targets[@]}"; do
  # libFuzzer's final statistics (also printed when the run is interrupted).
  n=$(awk '/^stat::number_of_executed_units:/ { print $2 }' "$out/$t.log" | tail -1)
  s=$(cat "$out/$t.seconds" 2>/dev/null || true)
  n=${n:-0}
  s=${s:-0}
  total=$((total + n))
  printf '%-14s %12s %9.0f %10.0f\n' "$t" "$n" "$s" "$(awk -v n="$n" -v s="$s" 'BEGIN { print (s > 0 ? n / s : 0) }')"
done
echo "total executions: $total"
ls "$out"/*-crash-* "$out"/*-leak-* "$out"/*-timeout-* "$out"/*-oom-* 2>/dev/null && failed=1
[ "$failed" = 0 ] && echo "clean" || echo "NOT clean"
exit "$failed"
