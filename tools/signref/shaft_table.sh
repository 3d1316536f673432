#!/usr/bin/env bash
# The light-shaft error table (issue 15): for each view, the game's half-resolution volume buffer
# (what its volumetric pass estimated) against obscura_signref's ray-traced truth of the same pose,
# haze and smoke, as RMSE over rgb, beside the RMSE of no shafts at all (an all-zero frame: the
# baseline) and their ratio (game / off: below 1 the shafts help, 0 is perfect). Images and
# results land in $OUT (default build/shaft_table/), the markdown table on stdout and in table.md.
# Beside them, the header's law integrated by the reference (--law) against the truth: the part of
# the game's error that is the law's (a spherical lamp seen obliquely: README) and not its pass's.
#
# Usage: xvfb-run -a -s "-screen 0 1920x1080x24" tools/signref/shaft_table.sh [GAME]
#        (GAME defaults to build/game/obscura; after scripts/build.sh or a build of obscura and
#        obscura_signref). VIEWS="sign_front along" runs a subset; SPP=, STEP=, LAMP=, THREADS=
#        set the reference's sampling; W= H= the game's window (the volume buffer is half of it).
#
# The game's flags (being added by the lead; the names may change: edit them here):
#   VOLUME_DUMP_FLAG FILE  the half-resolution volume buffer at the screenshot tick, PFM, rgb =
#                          in-scattered radiance (tools/signref/README.md)
#   SMOKE_DUMP_FLAG FILE   the live smoke grids at that tick (engine_ext/smoke/smoke_dump.h)
#   HAZE_ARGS              what sets the game's uniform haze to HAZE per metre (empty: its default,
#                          which HAZE must then equal)
set -euo pipefail
cd "$(dirname "$0")/../.."
VOLUME_DUMP_FLAG=${VOLUME_DUMP_FLAG:---volume-dump}
SMOKE_DUMP_FLAG=${SMOKE_DUMP_FLAG:---smoke-dump}
HAZE=${HAZE:-0.03}                       # the game's default (engine_ext/signs/sign_knobs.h)
HAZE_ARGS=${HAZE_ARGS:-"--sign-haze $HAZE"}
# The game's haze only scatters (its extinction is neglected: shaders/signs/sign_march.glsl): the
# reference integrates the same model. HAZE_EXTINCTION=$HAZE gives the physical haze instead.
HAZE_EXTINCTION=${HAZE_EXTINCTION:-0}
GAME_ARGS=${GAME_ARGS:-"--hud off"}      # anything else every game run gets
game=${1:-build/game/obscura}
ref=${SIGNREF:-build/tools/signref/obscura_signref}
OUT=${OUT:-build/shaft_table}
W=${W:-1280}; H=${H:-720}; FOV=${FOV:-90}; TICKS=${TICKS:-2}
SPP=${SPP:-4}; STEP=${STEP:-0.02}; LAMP=${LAMP:-16}; THREADS=${THREADS:-$(nproc)}
mkdir -p "$OUT"
export XDG_CACHE_HOME="$(pwd)/build/cache"
for bin in "$game" "$ref"; do [ -x "$bin" ] || { echo "shaft_table: $bin is not built" >&2; exit 2; }; done

arena=media/levels/arena.map room=tests/signs/levels/sign_room.map
# name | level | eye "x y z yaw pitch" (world metres, degrees; yaw 0 faces -z, 90 faces -x) |
# optional replay (instead of --start-pose: e.g. one that throws a smoke grenade into the beam; the
# dump is taken at its screenshot tick). Arena poses: engine_ext/signs/README.md (room C's EXIT).
views=(
  # tests/signs/levels/sign_room.map: the replays' views (tests/replay/scripts/sign_*.replay)
  "front|$room|9 1.65 -4 90 8"                    # facing the sign across the room
  "side|$room|6 1.65 -7.5 180 5"                  # from the south wall, across the beam
  "inside|$room|6 1.65 -4.3 0 0"                  # in the beam, looking across it (sign off-screen)
  "behind|$room|-1.5 1.65 -4 -90 5"               # behind the sign, through the doorway
  "lamp_behind|$room|3 1.65 -4 -90 -10"           # the lamp behind the camera, along the light
  "smoke|$room||tests/signs/shaft_smoke.replay"   # a grenade's cloud in the beam, from the side
  "arena_at_sign|$arena|32 1.65 -52 104 -5"       # the arena's room C: its EXIT sign across the room
)
picked() { [ -z "$2" ] || [[ " ${2//,/ } " == *" $1 "* ]]; }

rows=()
: > "$OUT/results.txt"
for v in "${views[@]}"; do
  IFS='|' read -r name level pose replay <<< "$v"
  picked "$name" "${VIEWS:-}" || continue
  vol="$OUT/${name}_game.pfm" smoke="$OUT/${name}_smoke.dump" shot="$OUT/${name}_game.png"
  rm -f "$vol" "$smoke"
  # shellcheck disable=SC2086  # the *_ARGS are word lists
  if [ -n "${replay:-}" ]; then
    "$game" --replay "$replay" $GAME_ARGS $HAZE_ARGS --screenshot "$shot" "$VOLUME_DUMP_FLAG" "$vol" "$SMOKE_DUMP_FLAG" "$smoke" > "$OUT/${name}_game.log" 2>&1
  else
    "$game" --headless --ticks "$TICKS" --width "$W" --height "$H" --level "$level" --start-pose "$pose" \
      $GAME_ARGS $HAZE_ARGS --screenshot "$shot" "$VOLUME_DUMP_FLAG" "$vol" "$SMOKE_DUMP_FLAG" "$smoke" > "$OUT/${name}_game.log" 2>&1
  fi || { echo "shaft_table: the game failed on $name (see $OUT/${name}_game.log)" >&2; exit 1; }
  [ -f "$vol" ] || { echo "shaft_table: the game wrote no $vol ($VOLUME_DUMP_FLAG; see $OUT/${name}_game.log)" >&2; exit 1; }
  # the pose the game really used (it may move the eye out of the floor)
  used=$(sed -n 's/^camera-pose //p' "$OUT/${name}_game.log" | tail -n 1)
  [ -n "$used" ] || used=$pose
  smoke_args=()
  grep -qa "^volumes [1-9]" "$smoke" 2>/dev/null && smoke_args=(--smoke "$smoke")
  line=$("$ref" --level "$level" --pose "$used" --fov "$FOV" --haze "$HAZE" --haze-extinction "$HAZE_EXTINCTION" "${smoke_args[@]}" --spp "$SPP" --step "$STEP" \
           --lamp-samples "$LAMP" --threads "$THREADS" --out "$OUT/${name}_ref.pfm" --png "$OUT/${name}_ref.png" \
           --compare "$vol" 2> "$OUT/${name}_ref.log" | grep '^signref ')
  # the game's law (signIrradiance, one occlusion ray) by the same integrator against the truth:
  # the error a perfect estimator of the law would still have
  law=$("$ref" --level "$level" --pose "$used" --fov "$FOV" --haze "$HAZE" --haze-extinction "$HAZE_EXTINCTION" "${smoke_args[@]}" --spp "$SPP" --step "$STEP" \
          --law --threads "$THREADS" --compare "$OUT/${name}_ref.pfm" 2>> "$OUT/${name}_ref.log" | sed -n 's/^signref rmse=\([^ ]*\).*/\1/p')
  rmse=$(sed -n 's/.* rmse=\([^ ]*\).*/\1/p' <<< "$line")
  off=$(sed -n 's/.* rmse_off=\([^ ]*\).*/\1/p' <<< "$line")
  mean=$(sed -n 's/.* mean_ref=\([^ ]*\).*/\1/p' <<< "$line")
  ratio=$(awk -v a="$rmse" -v b="$off" 'BEGIN { if (b > 0) printf "%.3f", a / b; else print "n/a" }')
  smoke_note=no; [ ${#smoke_args[@]} -gt 0 ] && smoke_note=yes
  rows+=("| $name | \`$used\` | $smoke_note | $rmse | $off | $ratio | $law | $mean |")
  echo "$line view=$name" >> "$OUT/results.txt"
done

{
  echo "RMSE over rgb of the game's half-resolution volume buffer against obscura_signref (spp $SPP, step $STEP m, $LAMP lamp samples, haze $HAZE/m); off = an all-zero buffer (no shafts); ratio = game / off; RMSE law = the header's law (throughSign, one occlusion ray) integrated the same way, against the truth: the floor for an exact estimator of the law."
  echo
  echo "| view | pose | smoke | RMSE game | RMSE off | ratio | RMSE law | mean ref |"
  echo "|---|---|---|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
} | tee "$OUT/table.md"
