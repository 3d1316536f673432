#!/usr/bin/env bash
# The frame's budget (bench/timedemo_budget.replay, bench/budget.py): one 1280x720 run headless
# under Xvfb, 200 decals scattered in view in every segment; prints the timedemo and the table.
# Usage: bench/run_budget.sh [extra game arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
export XDG_CACHE_HOME="$(pwd)/build/cache"
uptime
xvfb-run -a -s "-screen 0 1920x1080x24" build/game/obscura --headless --timedemo bench/timedemo_budget.replay \
  --debug-decals 200 --debug-decals-cone 40 "$@" | tee /dev/stderr | bench/budget.py
uptime
