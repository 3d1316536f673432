#!/usr/bin/env bash
# Builds obscura_smokebench in a Release build dir (build-release-smoke/) and runs it twice: on the
# machine as it is, then with as many competing CPU-bound processes as there are cores (the thread
# pool on an oversubscribed machine). The output is also written to
# bench/results/smoke_<UTC date-time>.txt (bench/results is git-ignored).
# Usage: bench/run_smoke_bench.sh [--threads N] [--quick] [--baseline]
# The machine's other load skews the figures: the roofline's bandwidths and peak are measured in
# the same run, so compare the ratios, and rerun on an idle machine for absolute times.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-release-smoke
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target obscura_smokebench -j"$(nproc)" >/dev/null
mkdir -p bench/results
out="bench/results/smoke_$(date -u +%Y%m%d_%H%M%S).txt"
{
  echo "# $(date -u '+%Y-%m-%d %H:%M:%S UTC'), $(git rev-parse --short HEAD 2>/dev/null || echo '?'), $(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
  echo "# load average before the run: $(cut -d' ' -f1-3 /proc/loadavg)"
  "$build/tools/smokebench/obscura_smokebench" "$@"
  echo
  echo "# the same with $(nproc) competing CPU-bound processes (the thread pool oversubscribed)"
  "$build/tools/smokebench/obscura_smokebench" --quick --compete "$(nproc)" "$@"
} | tee "$out"
echo "results: $out"
