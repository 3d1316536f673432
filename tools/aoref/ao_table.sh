#!/usr/bin/env bash
# The AO error/cost table: for each view, the ray-traced reference (obscura_aoref, 256 rays/pixel,
# radius 0.6 m) against each AO mode's AO-only frame from the game (same pose, 320x180, no HUD),
# as mean absolute error, RMSE and bias (mode - reference). Images land in build/ao_table/.
# Usage: tools/aoref/ao_table.sh   (after scripts/build.sh; needs an X server: run under xvfb-run)
set -euo pipefail
cd "$(dirname "$0")/../.."
game=build/game/obscura
ref=build/tools/aoref/obscura_aoref
out=build/ao_table
mkdir -p "$out"
W=320; H=180; R=${RADIUS:-0.6}; I=${INTENSITY:-2}  # knobs: RADIUS=, INTENSITY= in the environment
# name | level | eye "x y z yaw pitch" (metres, degrees)
views=(
  "courtyard|media/levels/arena.map|26 1.65 -24 -30 -10"
  "pillars|media/levels/arena.map|25 1.65 -32 0 -15"
  "low_angle|media/levels/arena.map|32 0.4 -22 0 -5"
  "wall_off_screen|media/levels/arena.map|43 1.65 -30 90 -35"
  "e3m4_start|../shared/maps/librequake/e3m4.map|30 46.15 10.5 0 -10"
  "e3m4_corridor|../shared/maps/librequake/e3m4.map|30 46.15 5 30 -20"
  "sibenik_nave|tests/ssao/views/sibenik.map|0 1.65 0 90 0"
  "sibenik_pillars|tests/ssao/views/sibenik.map|0 1.65 0 -90 -10"
)
modes=(crytek hemisphere cone horizon)
printf '| view | mode | MAE | RMSE | bias |\n|---|---|---|---|---|\n'
for v in "${views[@]}"; do
  IFS='|' read -r name level pose <<<"$v"
  [ -f "$level" ] || { echo "| $name | (no $level) | | | |"; continue; }
  for m in "${modes[@]}"; do
    "$game" --headless --ticks 1 --width $W --height $H --level "$level" --start-pose "$pose" --hud off \
      --ssao "$m" --ssao-radius $R --ssao-intensity $I --ao-only --screenshot "$out/${name}_$m.png" >/dev/null
    line=$("$ref" --level "$level" --pose "$pose" --width $W --height $H --radius $R --rays 256 \
      --out "$out/${name}_reference.png" --compare "$out/${name}_$m.png" 2>/dev/null)
    read -r _ mae rmse bias _ <<<"$line"
    printf '| %s | %s | %s | %s | %s |\n' "$name" "$m" "${mae#mae=}" "${rmse#rmse=}" "${bias#bias=}"
  done
done

# The side-by-side image of the modes (for the READMEs): the lit scene, each mode's AO, the reference.
if [ -x build/tools/aoref/obscura_side_by_side ] && [ -f "$out/sibenik_nave_reference.png" ]; then
  pose="0 1.65 0 90 0"
  "$game" --headless --ticks 1 --width $W --height $H --level tests/ssao/views/sibenik.map --start-pose "$pose" \
    --hud off --screenshot "$out/sibenik_nave_scene.png" >/dev/null
  build/tools/aoref/obscura_side_by_side "$out/ao_modes_sibenik.png" "$out/sibenik_nave_scene.png" \
    "$out/sibenik_nave_crytek.png" "$out/sibenik_nave_hemisphere.png" "$out/sibenik_nave_cone.png" \
    "$out/sibenik_nave_horizon.png" \
    "$out/sibenik_nave_reference.png"
  echo "side by side: $out/ao_modes_sibenik.png (scene | crytek | hemisphere | cone | horizon | ray-traced reference)"
fi
