#!/usr/bin/env bash
# tools/signref/shaft_table.sh end to end with fake_game.sh (a buffer of zeros): one row per view,
# and a game of zeros scores exactly the off baseline (ratio 1.000).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
OUT=$out SIGNREF=$1 W=48 H=28 SPP=1 STEP=0.1 LAMP=2 THREADS=2 VIEWS="front side" \
  "$here/../../tools/signref/shaft_table.sh" "$here/fake_game.sh" > "$out/stdout"
cat "$out/stdout"
[ "$(grep -c "^| \(front\|side\) " "$out/table.md")" = 2 ] || { echo "FAIL: expected two rows"; exit 1; }
grep -q '^| front | `9 1.65 -4 90 8` | no | .* | 1.000 |' "$out/table.md" || { echo "FAIL: front's row"; exit 1; }
[ -f "$out/side_ref.pfm" ] && [ -f "$out/side_ref.png" ] || { echo "FAIL: no reference images"; exit 1; }
[ "$(wc -l < "$out/results.txt")" = 2 ] || { echo "FAIL: results.txt"; exit 1; }
echo PASS
