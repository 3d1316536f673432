#!/usr/bin/env bash
# Re-makes every replay test's reference images (tests/replay/references/<name>/) from the
# current build, after a change whose new frames you have reviewed. Look at the new PNGs
# (git diff --stat tests/replay/references) before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
export XDG_CACHE_HOME="$(pwd)/build/cache" OBSCURA_REBASELINE=1
xvfb-run -a -s "-screen 0 1280x1024x24" ctest --test-dir build -L replay --output-on-failure "$@"
git status --short tests/replay/references
