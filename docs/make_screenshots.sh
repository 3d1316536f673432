#!/usr/bin/env bash
# Re-makes the README's game screenshots in docs/screenshots/ from the current build (look at them
# before committing). The AO, frame-view and sign sheets are made by their techniques' tables
# (tools/aoref/ao_table.sh, engine_ext/frame/README.md, tools/signref/shaft_table.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
game=build/game/obscura
export XDG_CACHE_HOME="$(pwd)/build/cache"
run() { xvfb-run -a -s "-screen 0 1280x1024x24" "$game" "$@" > /dev/null; }
for r in docs/screenshots.replay docs/screenshots_range.replay docs/screenshots_corridor.replay docs/screenshots_menu.replay; do
  run --replay "$r" --capture-dir docs/screenshots
done
run --headless --ticks 30 --width 960 --height 540 --level media/third_party/librequake/e3m4.map --screenshot docs/screenshots/e3m4.png
git status --short docs/screenshots
