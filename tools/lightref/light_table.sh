#!/usr/bin/env bash
# The light bake's error table (issue 32), one command: for each view, the path-traced irradiance
# (obscura_lightref: SAMPLES paths a pixel, 3 bounces) against the frame's (the game's
# --irradiance-dump: direct + ambient before AO, at the same pose and size), against the model
# before the bake (lightref's beforeTheBake) and against showing nothing, as luminance RMSE.
# Rows land in build/light_table/table.md; the PFMs beside it.
# Usage: xvfb-run -a -s "-screen 0 1280x1024x24" tools/lightref/light_table.sh   (after scripts/build.sh)
#        VIEWS="sealed corridor" runs a subset; SAMPLES=, W=, H= change the knobs.
set -euo pipefail
cd "$(dirname "$0")/../.."
game=build/game/obscura
ref=build/tools/lightref/obscura_lightref
out=build/light_table
mkdir -p "$out"
export XDG_CACHE_HOME="$(pwd)/build/cache"
W=${W:-160}; H=${H:-90}; SAMPLES=${SAMPLES:-256}
views_map=tests/lightbake/levels/light_views.map arena=media/levels/arena.map e3m4=media/third_party/librequake/e3m4.map
# name | level | eye "x y z yaw pitch" (world metres, degrees; yaw 0 faces -z, 90 faces -x)
views=(
  "sealed|$views_map|1 1.65 -1 -45 -10"          # room A: sealed on all sides under sun and sky dome, no lamp
  "thin_wall|$views_map|26.9 1.65 -4 90 -15"     # room C, looking at the 0.25 m wall with the lamp behind it
  "lamp_room|$views_map|13 1.65 -4 -90 -15"      # room B, the lamp's side of that wall
  "corridor|$views_map|46.9 1.65 -1.5 90 -5"     # a 16 m corridor open at its far end only
  "courtyard|$arena|26 1.65 -24 -30 -10"         # the arena's courtyard, sun, sky and bounce
  "room_c|$arena|24 1.65 -48 -90 -8"             # the arena's dark room C (env_ambient 0.1), its sign behind
  "e3m4_start|$e3m4|30 46.15 10.5 0 -10"         # LibreQuake e3m4's first corridor
  "e3m4_room_west|$e3m4|-53 30.15 -68.5 -90 -5"  # an e3m4 room
)
echo "| view | reference mean | RMSE: nothing | before the bake | the frame now | before / now |" > "$out/table.md"
echo "|---|---|---|---|---|---|" >> "$out/table.md"
for v in "${views[@]}"; do
  IFS='|' read -r name level pose <<< "$v"
  [ -n "${VIEWS:-}" ] && [[ " $VIEWS " != *" $name "* ]] && continue
  [ -f "$level" ] || { echo "skip $name: $level missing"; continue; }
  "$game" --level "$level" --headless --ticks 2 --hud off --ssao off --sign-mode off --width "$W" --height "$H" \
    --start-pose "$pose" --irradiance-dump "$out/$name.frame.pfm" > "$out/$name.log" 2>&1
  line=$("$ref" --level "$level" --pose "$pose" --width "$W" --height "$H" --samples "$SAMPLES" \
    --frame "$out/$name.frame.pfm" --out "$out/$name.ref.pfm")
  echo "$name: $line"
  /usr/bin/python3 - "$name" "$line" >> "$out/table.md" <<'PY'
import re, sys
name, line = sys.argv[1], sys.argv[2]
f = lambda k: float(re.search(k + r" ([0-9.]+)", line).group(1))
before, now = f("before the bake"), f("the frame")
ratio = "%.1f×" % (before / now) if now > 0 else ("∞ (0 now)" if before > 0 else "—")
print("| %s | %.4f | %.4f | %.4f | %.4f | %s |" % (name, f("reference mean"), f("nothing"), before, now, ratio))
PY
done
cat "$out/table.md"
