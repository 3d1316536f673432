#!/usr/bin/env bash
# A stand-in for the game in shaft_table_test.sh: writes what the game's dump flags will (a
# half-resolution PFM of zeros for --volume-dump, an empty smoke dump for --smoke-dump) and the
# camera-pose line, so the table's plumbing is tested without a GPU or an X server.
set -euo pipefail
w=64 h=36 vol= smoke= pose=
while [ $# -gt 0 ]; do
  case $1 in
    --width) w=$2; shift ;;
    --height) h=$2; shift ;;
    --volume-dump) vol=$2; shift ;;
    --smoke-dump) smoke=$2; shift ;;
    --start-pose) pose=$2; shift ;;
  esac
  shift
done
python3 - "$vol" $((w / 2)) $((h / 2)) <<'PY'
import struct, sys
path, w, h = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
with open(path, "wb") as f:
    f.write(b"PF\n%d %d\n-1.0\n" % (w, h) + struct.pack("<%df" % (w * h * 3), *([0.0] * (w * h * 3))))
PY
printf 'obscura-smoke-dump 1\ntime 0 sigma 1\nvolumes 0\n' > "$smoke"
echo "camera-pose $pose"
