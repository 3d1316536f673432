#!/usr/bin/env bash
# Builds Obscura and launches it on the default level (extra arguments go to the game, e.g.
# --level media/third_party/librequake/e3m4.map). On a machine with no X display it runs headless
# under Xvfb instead and writes a screenshot to out/, saying where.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh obscura obscura_textures

if [ -n "${DISPLAY:-}" ]; then
  exec build/game/obscura "$@"
fi

mkdir -p out
shot="$(pwd)/out/play-$(date +%Y%m%d-%H%M%S).png"
echo "play: no X display here, running headless under Xvfb (300 ticks at 1280x720)"
export XDG_CACHE_HOME="${XDG_CACHE_HOME:-$(pwd)/out/cache}"
xvfb-run -a -s "-screen 0 1280x720x24" build/game/obscura --headless --width 1280 --height 720 \
  --ticks 300 --screenshot "$shot" "$@"
echo "play: screenshot written to $shot"
