#!/usr/bin/env bash
# The AO error/cost table, one command. For each view, the ray-traced reference (obscura_aoref,
# 256 rays/pixel, scored at 320x180) against each AO configuration's AO-only frame from the game
# (same pose, no HUD) and against `off` (an all-white frame, scored by the same code), as
# whole-frame MAE, and MAE and bias (mode - reference) over the occluded region (reference < 0.95:
# aoref/ao_compare.h). The game renders at SCALE (4) times the scored size, 1280x720, the size the
# cost is measured at, and the truth traces the same 1280x720 pixels with 256/SCALE^2 rays each;
# both are averaged over SCALE x SCALE blocks (a 320x180 game would score an 80x45 AO buffer that
# nobody plays at). Two truths: the local radius (LOCAL_RADIUS, 0.6 m: the game's default
# --ssao-radius) and a large-scale one (LARGE_RADIUS, 2 m). Each configuration is scored against a
# truth when asked for its radius (its radius knob set to it: --ssao-radius for the one-radius
# modes; --ssao-large-radius for `combined`, whose small scale stays at the local radius, so at the
# local radius it is its small term alone), and against the large-scale truth also at its defaults
# (the frame the game really shows).
# Then every configuration's frame time at 1280x720 from one timedemo run
# (bench/timedemo_ao.replay). Images, results.tsv and the tables land in build/ao_table/ (table.md).
# Usage: xvfb-run -a -s "-screen 0 1920x1080x24" tools/aoref/ao_table.sh   (after scripts/build.sh)
#        VIEWS="courtyard sibenik_nave" / CONFIGS="horizon cone" run a subset (names below);
#        LOCAL_RADIUS=, LARGE_RADIUS=, INTENSITY=, RAYS=, SCALE= change the knobs; NO_COST=1 skips the timedemo.
set -euo pipefail
cd "$(dirname "$0")/../.."
game=build/game/obscura
ref=build/tools/aoref/obscura_aoref
out=build/ao_table
mkdir -p "$out"
export XDG_CACHE_HOME="$(pwd)/build/cache"
W=320; H=180; I=${INTENSITY:-2}; RAYS=${RAYS:-256}; S=${SCALE:-4}; GW=$((W * S)); GH=$((H * S))
RL=${LOCAL_RADIUS:-0.6}; RG=${LARGE_RADIUS:-2}
arena=media/levels/arena.map e3m4=media/third_party/librequake/e3m4.map sibenik=tests/ssao/views/sibenik.map
# name | level | eye "x y z yaw pitch" (world metres, degrees; yaw 0 faces -z, 90 faces -x; the arena's
# map (x, y, z) is world (x, z, -y)) | crouch: the pose is a standing one and the player crouches (a
# replay holding lctrl: the eye drops to 0.956 m; --start-pose alone cannot put the eye that low, the
# standing player is pushed out of the floor). Views chosen to hurt screen-space AO.
views=(
  "courtyard|$arena|26 1.65 -24 -30 -10"                  # the open courtyard towards the pillars and the north wall
  "pillars|$arena|25 1.65 -32 0 -15"                      # four 0.25 m pillars, 5 m tall, 4 m ahead
  "pillars_close|$arena|24.6 1.65 -34.6 10 -25"           # the pillars' feet from 1.5 m
  "low_angle|$arena|32 1.65 -22 0 -2"                     # along the courtyard floor, nearly level
  "low_eye_tall_wall|$arena|43.3 1.65 -21 0 0|crouch"     # eye 0.96 m, 0.7 m from the 12 m east wall, along it
  "wall_off_screen|$arena|43 1.65 -30 90 -35"             # the 12 m east wall right behind the camera
  "wall_off_side|$arena|42.8 1.65 -27 45 -20"             # the east wall just past the right edge
  "crouch_cover|$arena|32 1.65 -25.6 0 -15|crouch"        # crouched 2.4 m from the 1.125 m cover wall
  "crouch_stairs|$arena|9 1.65 -39.2 -45 0|crouch"        # crouched in room B: the stairs, the mezzanine's underside
  "room_a|$arena|12 1.65 -22.8 0 10"                      # closed room A (4 m ceiling), from its south wall
  "room_b|$arena|8.5 1.65 -38.8 -10 15"                   # room B (6 m ceiling), the mezzanine and stairs
  "floor_down|$arena|32 1.65 -30 0 -70"                   # open courtyard floor, looking down: nothing occluded
  "e3m4_start|$e3m4|30 46.15 10.5 0 -10"                  # the first corridor
  "e3m4_corridor|$e3m4|30 46.15 5 30 -20"                 # its corner and steps
  "e3m4_room_west|$e3m4|-53 30.15 -68.5 -90 -5"           # a room: purple floor, ceiling, a pillar
  "e3m4_room_east|$e3m4|64 17.65 -69 -90 -5"              # a room: ceiling beams, a doorway
  "sibenik_nave|$sibenik|0 1.65 0 90 0"
  "sibenik_pillars|$sibenik|0 1.65 0 -90 -10"
)
# (No crates, barrels or targets in view: the reference traces brushes and misc_models only.)
# name | game arguments | the knob that sets its radius | which radius its defaults are (local or
# large: the frame the game shows). The order is bench/timedemo_ao.replay's segment order after `off`.
configs=(
  "crytek|--ssao crytek|--ssao-radius|local"
  "hemisphere|--ssao hemisphere|--ssao-radius|local"
  "cone|--ssao cone|--ssao-radius|local"
  "horizon|--ssao horizon|--ssao-radius|local"
  "heightfield|--ssao heightfield|--ssao-radius|local"
  "gtao|--ssao gtao|--ssao-radius|local"
  "combined|--ssao combined|--ssao-large-radius|large"
  "horizon-half|--ssao horizon --ssao-resolution half|--ssao-radius|local"
  "hemisphere-full-32|--ssao hemisphere --ssao-resolution full --ssao-samples 32|--ssao-radius|local"
)
# VIEWS= / CONFIGS= filters: names separated by spaces or commas.
picked() { [ -z "$2" ] || [[ " ${2//,/ } " == *" $1 "* ]]; }
# render NAME LEVEL POSE CROUCH PNG ARGS...: the game's frame of a view; prints where the camera was.
render() {
  local name=$1 level=$2 pose=$3 crouch=$4 png=$5; shift 5
  if [ "$crouch" = crouch ]; then
    printf 'obscura-replay 1\nlevel %s\nseed 1\nresolution %s %s\nstart %s\n0 key lctrl down\n20 end\n' \
      "$level" $GW $GH "$pose" > "$out/$name.replay"
    "$game" --replay "$out/$name.replay" --hud off "$@" --screenshot "$png"
  else
    "$game" --headless --ticks 1 --width $GW --height $GH --level "$level" --start-pose "$pose" --hud off "$@" --screenshot "$png"
  fi | sed -n 's/^camera-pose //p'
}
# The image of configuration $2 at mode radius $3 in view $1 (no suffix at the local radius).
image() { if [ "$3" = "$RL" ]; then echo "$out/${1}_$2.png"; else echo "$out/${1}_$2_r$3.png"; fi; }

results="$out/results.tsv"
ran_views=() ran_configs=()
for c in "${configs[@]}"; do picked "${c%%|*}" "${CONFIGS:-}" && ran_configs+=("$c"); done
# A filtered run replaces its own rows of the last results (its views' `off` and its configurations)
# and keeps the rest, so the table can be brought up to date a few views at a time.
if [ -n "${VIEWS:-}${CONFIGS:-}" ] && [ -f "$results" ]; then
  keep=$(awk -F'\t' -v views="${VIEWS:-}" -v configs="$(for c in "${ran_configs[@]}"; do printf '%s ' "${c%%|*}"; done)" '
    BEGIN { gsub(",", " ", views); nv = split(views, v, " "); for (i in v) V[v[i]]; split(configs, c, " "); for (i in c) C[c[i]]; C["off"] }
    NR == 1 || !((nv == 0 || $1 in V) && $4 in C)' "$results")
  printf '%s\n' "$keep" > "$results"
else
  printf 'view\ttruth_radius\tmode_radius\tconfig\tmae\trmse\tbias\tpixels\toccluded_mae\toccluded_bias\toccluded_pixels\toccluded_share\n' > "$results"
fi
for v in "${views[@]}"; do
  IFS='|' read -r name level pose crouch <<<"$v"
  picked "$name" "${VIEWS:-}" || continue
  if [ ! -f "$level" ]; then echo "ao_table: $name: no $level, skipped" >&2; continue; fi
  ran_views+=("$v")
  # The game's frames at both mode radii; the reference is traced from where the game's camera
  # really was (physics may nudge the player), once per truth radius for all of them.
  seen=""
  for r in $(printf '%s\n' "$RL" "$RG" | uniq); do
    for c in "${ran_configs[@]}"; do
      IFS='|' read -r cname cargs knob _ <<<"$c"
      # shellcheck disable=SC2086
      p=$(render "$name" "$level" "$pose" "$crouch" "$(image "$name" "$cname" "$r")" $cargs "$knob" "$r" \
        --ssao-intensity "$I" --ao-only)
      if [ -z "$seen" ]; then seen=$p; echo "ao_table: $name: asked '$pose', camera at '$p'" >&2
      elif [ "$p" != "$seen" ]; then echo "ao_table: $name: $cname saw '$p', not '$seen'" >&2; exit 1; fi
    done
  done
  for tr in $(printf '%s\n' "$RL" "$RG" | uniq); do
    # Against the local truth: the modes at the local radius. Against the large-scale truth: the
    # modes at the local radius (the default) and at the large one.
    compares=() modeRadii=("$RL"); [ "$tr" = "$RL" ] || modeRadii+=("$tr")
    for r in "${modeRadii[@]}"; do
      for c in "${ran_configs[@]}"; do compares+=(--compare "$(image "$name" "${c%%|*}" "$r")"); done
    done
    refimg="$out/${name}_reference.png"; [ "$tr" = "$RL" ] || refimg="$out/${name}_reference_r$tr.png"
    "$ref" --level "$level" --pose "$seen" --width $W --height $H --scale "$S" --radius "$tr" --rays "$RAYS" --out "$refimg" \
      --compare-off "${compares[@]}" 2>/dev/null | while read -r _ mae rmse bias px omae obias opx oshare file; do
        file=${file#file=}
        if [ "$file" = off ]; then cname=off r=-
        else
          base=$(basename "$file" .png); base=${base#"${name}_"}
          case "$base" in *_r"$tr") cname=${base%_r"$tr"}; r=$tr ;; *) cname=$base; r=$RL ;; esac
        fi
        printf '%s\t%s\t%s\t%s' "$name" "$tr" "$r" "$cname"
        for kv in "$mae" "$rmse" "$bias" "$px" "$omae" "$obias" "$opx" "$oshare"; do printf '\t%s' "${kv#*=}"; done
        printf '\n'
      done >> "$results"
  done
done

table="$out/table.md"
/usr/bin/python3 tools/aoref/ao_table_format.py "$results" --local "$RL" --large "$RG" --intensity "$I" --rays "$RAYS" \
  --scale "$S" --defaults "$(for c in "${configs[@]}"; do IFS='|' read -r n _ _ d <<<"$c"; printf '%s=%s ' "$n" "$d"; done)" \
  --views "$(for v in "${views[@]}"; do printf '%s ' "${v%%|*}"; done)" \
  --configs "$(for c in "${configs[@]}"; do printf '%s ' "${c%%|*}"; done)" > "$table"

if [ -z "${NO_COST:-}" ]; then
  "$game" --headless --timedemo bench/timedemo_ao.replay > "$out/timedemo_ao.txt"
  # Per segment: wall mean, wall added, CPU added (process CPU time: steadier on a shared machine).
  mapfile -t added < <(grep '^timedemo-segment ' "$out/timedemo_ao.txt" |
    sed 's/.* mean_ms=\([0-9.]*\).* added_ms=\([-0-9.]*\) cpu_ms=[0-9.]* added_cpu_ms=\([-0-9.]*\).*/\1 \2 \3/')
  {
    printf '\nFrame time at 1280x720 (bench/timedemo_ao.replay, %s): mean ms; the cost over off in wall time and in\n' \
      "$(grep -o 'llvmpipe[^|]*\|NVIDIA[^|]*' "$out/timedemo_ao.txt" | head -1 || true)"
    printf 'process CPU time, each also as a share of the full-resolution 32-sample hemisphere'"'"'s cost:\n\n'
    printf '| off |'; for c in "${configs[@]}"; do printf ' %s |' "${c%%|*}"; done; printf '\n|---|'
    for c in "${configs[@]}"; do printf -- '---|'; done; printf '\n'
    read -r offMs _ <<<"${added[0]}"; printf '| %.1f |' "$offMs"
    read -r _ full fullCpu <<<"${added[${#configs[@]}]}"
    for i in "${!configs[@]}"; do
      read -r ms a cpu <<<"${added[$((i + 1))]}"
      printf ' %.1f (+%.1f = %.2f; cpu +%.0f = %.2f) |' "$ms" "$a" "$(awk "BEGIN{print $a / $full}")" "$cpu" \
        "$(awk "BEGIN{print $cpu / $fullCpu}")"
    done
    printf '\n'
  } >> "$table"
fi
cat "$table"

# The side-by-side images of the modes (for the READMEs): the lit scene, each configuration's AO
# at its defaults (the frame the game shows) and the ray-traced references at both radii, scaled to
# the scored size, in a grid of 3 columns, for the courtyard and the Sibenik nave (when they and
# every configuration ran).
[ ${#ran_configs[@]} -eq ${#configs[@]} ] || exit 0
small() { convert "$1" -scale "${W}x${H}" "$out/small_$(basename "$1")"; echo "$out/small_$(basename "$1")"; }
for v in "${ran_views[@]}"; do
  IFS='|' read -r name level pose crouch <<<"$v"
  case "$name" in courtyard | sibenik_nave) ;; *) continue ;; esac
  render "$name" "$level" "$pose" "$crouch" "$out/${name}_scene.png" >/dev/null
  images=("$(small "$out/${name}_scene.png")")
  for c in "${configs[@]}"; do
    IFS='|' read -r cname _ _ d <<<"$c"
    r=$RL; [ "$d" = large ] && r=$RG
    images+=("$(small "$(image "$name" "$cname" "$r")")")
  done
  build/tools/aoref/obscura_side_by_side --columns 3 "$out/ao_modes_$name.png" "${images[@]}" \
    "$out/${name}_reference.png" "$out/${name}_reference_r$RG.png"
  echo "side by side: $out/ao_modes_$name.png (scene | ${configs[*]%%|*} at their defaults | reference $RL m, $RG m)"
done
