#!/usr/bin/env bash
# Builds Obscura and runs the whole test suite headless (under Xvfb + Mesa llvmpipe).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
export XDG_CACHE_HOME="$(pwd)/build/cache"
mkdir -p "$XDG_CACHE_HOME"
xvfb-run -a -s "-screen 0 1280x1024x24" ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
