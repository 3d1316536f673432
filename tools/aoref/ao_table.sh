#!/usr/bin/env bash
# The AO error/cost table, one command: for each view, the ray-traced reference (obscura_aoref, 256
# rays/pixel) against each AO configuration's AO-only frame from the game (same pose, 320x180, no
# HUD), as mean absolute error, RMSE and bias (mode - reference); then every configuration's frame
# time at 1280x720 from one timedemo run (bench/timedemo_ao.replay: one view, the configurations
# one after another, so their costs over `off` compare on the same frame). Images and the tables
# land in build/ao_table/ (table.md).
# Usage: xvfb-run -a -s "-screen 0 1920x1080x24" tools/aoref/ao_table.sh   (after scripts/build.sh)
#        RADIUS=, INTENSITY= in the environment change the knobs; NO_COST=1 skips the timedemo.
set -euo pipefail
cd "$(dirname "$0")/../.."
game=build/game/obscura
ref=build/tools/aoref/obscura_aoref
out=build/ao_table
mkdir -p "$out"
export XDG_CACHE_HOME="$(pwd)/build/cache"
W=320; H=180; R=${RADIUS:-0.6}; I=${INTENSITY:-2}
# name | level | eye "x y z yaw pitch" (metres, degrees). Views chosen to hurt screen-space AO.
views=(
  "courtyard|media/levels/arena.map|26 1.65 -24 -30 -10"
  "pillars|media/levels/arena.map|25 1.65 -32 0 -15"
  "low_angle|media/levels/arena.map|32 1.65 -22 0 -2"
  "wall_off_screen|media/levels/arena.map|43 1.65 -30 90 -35"
  "e3m4_start|../shared/maps/librequake/e3m4.map|30 46.15 10.5 0 -10"
  "e3m4_corridor|../shared/maps/librequake/e3m4.map|30 46.15 5 30 -20"
  "sibenik_nave|tests/ssao/views/sibenik.map|0 1.65 0 90 0"
  "sibenik_pillars|tests/ssao/views/sibenik.map|0 1.65 0 -90 -10"
)
# name | game arguments. The order is bench/timedemo_ao.replay's segment order after `off`.
configs=(
  "crytek|--ssao crytek"
  "hemisphere|--ssao hemisphere"
  "cone|--ssao cone"
  "horizon|--ssao horizon"
  "heightfield|--ssao heightfield"
  "horizon-half|--ssao horizon --ssao-resolution half"
  "hemisphere-full-32|--ssao hemisphere --ssao-resolution full --ssao-samples 32"
)

declare -A sumMae sumRmse sumBias count cost
table="$out/table.md"
{
  printf 'Radius %s m, intensity %s, 16 samples at quarter resolution (the defaults) unless named; MAE / RMSE / bias (mode - reference)\n\n' "$R" "$I"
  printf '| view |'; for c in "${configs[@]}"; do printf ' %s |' "${c%%|*}"; done; printf '\n|---|'
  for c in "${configs[@]}"; do printf -- '---|'; done; printf '\n'
} > "$table"
for v in "${views[@]}"; do
  IFS='|' read -r name level pose <<<"$v"
  if [ ! -f "$level" ]; then echo "| $name | (no $level) |" >> "$table"; continue; fi
  row="| $name |"
  for c in "${configs[@]}"; do
    IFS='|' read -r cname cargs <<<"$c"
    # The reference is traced from where the game's camera really was (physics may nudge the player).
    # shellcheck disable=SC2086
    seen=$("$game" --headless --ticks 1 --width $W --height $H --level "$level" --start-pose "$pose" --hud off \
      $cargs --ssao-radius "$R" --ssao-intensity "$I" --ao-only --screenshot "$out/${name}_$cname.png" |
      sed -n 's/^camera-pose //p')
    line=$("$ref" --level "$level" --pose "$seen" --width $W --height $H --radius "$R" --rays 256 \
      --out "$out/${name}_reference.png" --compare "$out/${name}_$cname.png" 2>/dev/null)
    read -r _ mae rmse bias _ <<<"$line"
    mae=${mae#mae=}; rmse=${rmse#rmse=}; bias=${bias#bias=}
    row+=$(printf ' %.3f / %.3f / %+.3f |' "$mae" "$rmse" "$bias")
    sumMae[$cname]=$(awk "BEGIN{print ${sumMae[$cname]:-0} + $mae}")
    sumRmse[$cname]=$(awk "BEGIN{print ${sumRmse[$cname]:-0} + $rmse}")
    sumBias[$cname]=$(awk "BEGIN{print ${sumBias[$cname]:-0} + $bias}")
    count[$cname]=$(( ${count[$cname]:-0} + 1 ))
  done
  echo "$row" >> "$table"
done
row="| **mean** |"
for c in "${configs[@]}"; do
  n=${c%%|*}
  row+=$(awk "BEGIN{k=${count[$n]:-1}; printf \" **%.3f / %.3f / %+.3f** |\", ${sumMae[$n]:-0}/k, ${sumRmse[$n]:-0}/k, ${sumBias[$n]:-0}/k}")
done
echo "$row" >> "$table"

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

# The side-by-side images of the modes (for the READMEs): the lit scene, each configuration's AO and
# the ray-traced reference, in a grid of 3 columns, for the courtyard and the Sibenik nave.
for v in "courtyard|media/levels/arena.map|26 1.65 -24 -30 -10" "sibenik_nave|tests/ssao/views/sibenik.map|0 1.65 0 90 0"; do
  IFS='|' read -r name level pose <<<"$v"
  [ -f "$out/${name}_reference.png" ] || continue
  "$game" --headless --ticks 1 --width $W --height $H --level "$level" --start-pose "$pose" --hud off \
    --screenshot "$out/${name}_scene.png" >/dev/null
  images=("$out/${name}_scene.png")
  for c in "${configs[@]}"; do images+=("$out/${name}_${c%%|*}.png"); done
  build/tools/aoref/obscura_side_by_side --columns 3 "$out/ao_modes_$name.png" "${images[@]}" "$out/${name}_reference.png"
  echo "side by side: $out/ao_modes_$name.png (scene | ${configs[*]%%|*} | ray-traced reference)"
done
