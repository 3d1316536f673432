#!/usr/bin/env bash
# The whole suite under AddressSanitizer + UndefinedBehaviorSanitizer: builds build-asan/ with
# -DOBSCURA_SANITIZE=ON and runs every test there headless (replay tests included). Every game
# process the tests start inherits the options below, so a finding in any of them fails its test.
# Leaks are checked separately (LeakSanitizer on a short soak, tests/soak); here they are off,
# because Mesa, fontconfig and OGRE's plugins keep allocations to exit by design.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOBSCURA_SANITIZE=ON >/dev/null
cmake --build build-asan -j"$(nproc)"
export XDG_CACHE_HOME="$(pwd)/build-asan/cache"
mkdir -p "$XDG_CACHE_HOME"
# alloc_dealloc_mismatch=0: OGRE 1.12.10's STBI codec (Codec_STBI.so) hands stb_image's malloc'd
# pixels to an Ogre::Image that frees them with delete[]; every textured load trips it, in a
# library we do not build. Everything else is checked.
export ASAN_OPTIONS=detect_leaks=0:alloc_dealloc_mismatch=0:abort_on_error=1:detect_stack_use_after_return=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

xvfb-run -a -s "-screen 0 1280x1024x24" ctest --test-dir build-asan --output-on-failure \
  -j"$(nproc)" "$@"
