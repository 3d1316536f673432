#!/usr/bin/env bash
# Installs exactly the Debian 12 packages Obscura needs that are missing (idempotent).
# Used by scripts/play.sh, scripts/test.sh and .ci/run.
set -euo pipefail

PACKAGES=(
  # build
  cmake g++ make pkg-config
  # engine and libraries
  libogre-1.12-dev libbullet-dev libopenal-dev libsdl2-dev libboost-program-options-dev
  libimgui-dev libpng-dev
  # the decal baker's glyph masks (tools/decalbake)
  libfreetype-dev
  # the ray-traced AO reference (tools/aoref)
  libembree-dev
  # tests
  googletest libgtest-dev
  # headless rendering: Xvfb + Mesa llvmpipe
  xvfb xauth libgl1-mesa-dri
  # the window tests' real X events (tests/game/window_input_test.sh)
  xdotool
  # HUD font
  fonts-dejavu-core
  # the level generator's self-check test (tools/levelgen, stdlib only)
  python3
  # the fuzz targets' short run in the suite (tools/fuzz: libFuzzer, ASan, UBSan)
  clang
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
