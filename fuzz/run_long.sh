#!/bin/bash
# run_long.sh: the long fuzz run over the core's entry points (issue: at least 10^7 executions, clean).
#
# Runs the fast libFuzzer targets (fuzz_fit, fuzz_relate, fuzz_snap, fuzz_segment: ASan + UBSan, built by
# scripts/run-tests.sh or as in fuzz/CMakeLists.txt), each for a number of executions and from its own corpus
# under OUT, JOBS at a time. The corpora and a ledger (OUT/ledger.tsv: one line per target and run) are kept,
# so that a run can be stopped and resumed: a target stopped with kill -INT of its process counts the
# executions it ran, and the next run goes on from its corpus. Prints this run's executions, seconds and
# executions a second per target, the totals over the ledger, and whether every run was clean. Exits non-zero
# when a target found a crash, a leak, undefined behaviour or a broken invariant (its input is saved in OUT as
# <target>-crash-*, -leak-*, -timeout-* or -oom-*; replay it with `build-fuzz/fuzz/<target> FILE`).
#
# Usage: fuzz/run_long.sh [--build DIR] [--out DIR] [--jobs N] [--scale S] [--timeout S] [--targets LIST]
#   --build  the fuzz build tree (default build-fuzz)
#   --out    corpora, logs, ledger and crash inputs (default build-fuzz/long-run)
#   --jobs   targets run at once (default 4: all; the machine's cores are shared)
#   --scale  multiplies the executions per target (default 1: 10^7 in all; 0.01 for a quick try)
#   --timeout  seconds of wall time one input may take (default 10: the slowest inputs take about 0.5 s); a
#            run at low priority beside builds can stall an input that long, so give it more there (120)
#   --targets  comma-separated subset to run (default all four), e.g. fuzz_snap,fuzz_segment to spend a short
#            session's spare cores on the targets that run fastest
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-fuzz
out=
jobs=4
scale=1
timeout=10
only=
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --scale) scale=$2; shift 2 ;;
    --timeout) timeout=$2; shift 2 ;;
    --targets) only=$2; shift 2 ;;
    *) echo "usage: $0 [--build DIR] [--out DIR] [--jobs N] [--scale S] [--timeout S] [--targets LIST]" >&2; exit 2 ;;
  esac
done
out=${out:-$build/long-run}
mkdir -p "$out"

# Executions per target, 10^7 in all at scale 1, shared so that each takes about as long: with a grown corpus
# one core runs about 180 fit, 400 relate, 750 snap and 225 segment inputs a second (2026-11-26).
targets=(fuzz_fit fuzz_relate fuzz_snap fuzz_segment)
runs=(1000000 2000000 6000000 1000000)
if [ -n "$only" ]; then
  kept_targets=()
  kept_runs=()
  for t in ${only//,/ }; do
    found=
    for i in "${!targets[@]}"; do
      [ "${targets[$i]}" = "$t" ] && { kept_targets+=("$t"); kept_runs+=("${runs[$i]}"); found=1; }
    done
    [ -n "$found" ] || { echo "unknown target $t (targets: ${targets[*]})" >&2; exit 2; }
  done
  targets=("${kept_targets[@]}")
  runs=("${kept_runs[@]}")
fi

for t in "${targets[@]}"; do
  [ -x "$build/fuzz/$t" ] || { echo "$build/fuzz/$t is missing: build the fuzz targets first (see fuzz/CMakeLists.txt)" >&2; exit 2; }
done

run_one() {
  local t=$1 n=$2
  mkdir -p "$out/corpus_$t"
  local start
  start=$(date +%s.%N)
  local status=0
  "$build/fuzz/$t" -runs="$n" -timeout="$timeout" -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$out/$t-" "$out/corpus_$t" > "$out/$t.log" 2>&1 || status=$?
  awk -v end="$(date +%s.%N)" -v start="$start" 'BEGIN { print end - start }' > "$out/$t.seconds"
  # 72: libFuzzer's exit code when interrupted (Ctrl-C, kill -INT): the executions so far still count.
  [ "$status" = 72 ] && { echo "$t interrupted" >&2; status=0; }
  # libFuzzer's final statistics (also printed when the run is interrupted).
  local executed
  executed=$(awk '/^stat::number_of_executed_units:/ { print $2 }' "$out/$t.log" | tail -1)
  printf '%s\t%s\t%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$t" "${executed:-0}" "$(cat "$out/$t.seconds")" \
    "$([ "$status" = 0 ] && echo clean || echo FAILED)" >> "$out/ledger.tsv"
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

printf '%-14s %12s %9s %10s %16s\n' target executions seconds "exec/s" "ledger total"
for t in "${targets[@]}"; do
  n=$(awk '/^stat::number_of_executed_units:/ { print $2 }' "$out/$t.log" | tail -1)
  s=$(cat "$out/$t.seconds" 2>/dev/null || true)
  n=${n:-0}
  s=${s:-0}
  all=$(awk -F'\t' -v t="$t" '$2 == t { sum += $3 } END { print sum + 0 }' "$out/ledger.tsv")
  printf '%-14s %12s %9.0f %10.0f %16s\n' "$t" "$n" "$s" "$(awk -v n="$n" -v s="$s" 'BEGIN { print (s > 0 ? n / s : 0) }')" "$all"
done
awk -F'\t' '{ sum += $3; runs += 1; if ($5 != "clean") bad += 1 }
  END { printf "ledger: %d executions in %d target runs, %d not clean\n", sum, runs, bad }' "$out/ledger.tsv"
ls "$out"/*-crash-* "$out"/*-leak-* "$out"/*-timeout-* "$out"/*-oom-* 2>/dev/null && failed=1
[ "$failed" = 0 ] && echo "clean" || echo "NOT clean"
exit "$failed"
