#!/usr/bin/env bash
# Runs the standard timedemos (bench/timedemo_*.replay, 1280x720) headless under Xvfb and prints
# each summary; the machine-readable lines are also collected in bench/results/timedemo.txt.
# Usage: bench/run_timedemos.sh [extra game arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh obscura obscura_textures >/dev/null
mkdir -p bench/results
export XDG_CACHE_HOME="$(pwd)/build/cache"
out=bench/results/timedemo.txt
: > "$out"
for demo in bench/timedemo_*.replay; do
  xvfb-run -a -s "-screen 0 1920x1080x24" build/game/obscura --headless --timedemo "$demo" "$@" | tee /dev/stderr | grep '^timedemo name=' >> "$out"
done
echo "results: $out"
