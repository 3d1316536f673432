#!/usr/bin/env bash
# Runs each fuzz target on a copy of its seed corpus (tests/fuzz/corpus/<target>) for SECONDS
# seconds, with FUZZ_TIMEOUT s per input at most (default 2; a long run at low priority on a
# loaded machine needs more, or CPU starvation reads as a hang) and inputs up to 64 KiB; prints
# each target's executions and exits non-zero on the first finding (a crash-*/timeout-*/oom-* file
# under BUILD/findings).
# Usage: tools/fuzz/run_fuzz.sh BUILD_DIR SECONDS [target...]
set -euo pipefail
build=${1:?usage: run_fuzz.sh BUILD_DIR SECONDS [target...]}
seconds=${2:?usage: run_fuzz.sh BUILD_DIR SECONDS [target...]}
shift 2
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_map fuzz_replay fuzz_config)
here=$(cd "$(dirname "$0")" && pwd)
root=$here/../..
seeds=$root/tests/fuzz/corpus
# The project's own inputs seed the corpus too (read-only: libFuzzer writes into the first folder).
declare -A extra=([fuzz_map]=$root/media/levels [fuzz_replay]=$root/tests/replay/scripts [fuzz_config]="")
status=0
for t in "${targets[@]}"; do
  work=$build/corpus/$t findings=$build/findings/$t
  mkdir -p "$work" "$findings"
  cp -n "$seeds/$t"/* "$work"/ 2>/dev/null || true
  log=$build/$t.log
  set +e
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
    "$build/$t" -max_total_time="$seconds" -timeout="${FUZZ_TIMEOUT:-2}" -max_len=65536 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$findings/" "$work" ${extra[$t]} >"$log" 2>&1
  rc=$?
  set -e
  runs=$(grep -a -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  found=$(ls "$findings" | wc -l)
  echo "$t: $runs executions in ${seconds} s, corpus $(ls "$work" | wc -l) inputs, findings $found (exit $rc)"
  if [ $rc -ne 0 ] || [ "$found" -ne 0 ]; then
    status=1
    tail -40 "$log"
  fi
done
exit $status
