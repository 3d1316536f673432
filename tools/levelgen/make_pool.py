#!/usr/bin/env python3
"""Writes tests/sim/levels/pool.map: a pool to swim in (issue 17, liquids), for the swim tests and
the replay_pool_swim replay. Quake units (32 a metre), Valve-220 boxes as TrenchBroom writes them.

An open courtyard 14 x 10 m under the sky with a sun; a concrete deck at height 0; in it a pit
7 x 6 m, 2.5 m deep, tiled, holding water up to 0.25 m below the rim (`_wateralpha` 0.5: the tiles
show through). The water brush's top is *water1, its bottom *waterskip (not drawn); its sides lie
against the pit walls (hidden by the compiler). The player starts on the deck 2 m from the edge,
facing the pool (+X)."""
import sys

FACES = [  # (point, point, point) offsets from the min (0) or max (1) corner, and the texture axes
    ("min", [(0, 0, 0), (0, 1, 0), (0, 0, 1)], "[ 0 1 0 0 ] [ 0 0 -1 0 ]"),
    ("min", [(0, 0, 0), (0, 0, 1), (1, 0, 0)], "[ 1 0 0 0 ] [ 0 0 -1 0 ]"),
    ("min", [(0, 0, 0), (1, 0, 0), (0, 1, 0)], "[ 1 0 0 0 ] [ 0 -1 0 0 ]"),
    ("max", [(0, 0, 0), (0, 1, 0), (1, 0, 0)], "[ 1 0 0 0 ] [ 0 -1 0 0 ]"),
    ("max", [(0, 0, 0), (1, 0, 0), (0, 0, 1)], "[ 1 0 0 0 ] [ 0 0 -1 0 ]"),
    ("max", [(0, 0, 0), (0, 0, 1), (0, 1, 0)], "[ 0 1 0 0 ] [ 0 0 -1 0 ]"),
]


def box(lo, hi, tex, top=None, bottom=None):
    """A brush from lo to hi (Quake units); `top`/`bottom` override the +Z/-Z faces' texture."""
    lines = ["{"]
    for i, (corner, pts, axes) in enumerate(FACES):
        base = lo if corner == "min" else hi
        t = top if (i == 3 and top) else bottom if (i == 2 and bottom) else tex
        p = " ".join("( %d %d %d )" % tuple(base[k] + d[k] for k in range(3)) for d in pts)
        lines.append("%s %s %s 0 1 1" % (p, t, axes))
    lines.append("}")
    return "\n".join(lines)


M = 32  # units per metre
X, Y = 14 * M, 10 * M          # courtyard
PX0, PX1, PY0, PY1 = 4 * M, 11 * M, 2 * M, 8 * M  # the pit
BOTTOM, SURFACE = -80, -8      # pit floor 2.5 m down, water 0.25 m below the rim
WALL, TOP = 16, 5 * M

brushes = [
    # the deck around the pit (down to the pit's floor slab: its sides are the pit's walls)
    box((0, 0, BOTTOM - 16), (PX0, Y, 0), "concrete"),
    box((PX1, 0, BOTTOM - 16), (X, Y, 0), "concrete"),
    box((PX0, 0, BOTTOM - 16), (PX1, PY0, 0), "concrete"),
    box((PX0, PY1, BOTTOM - 16), (PX1, Y, 0), "concrete"),
    box((PX0, PY0, BOTTOM - 16), (PX1, PY1, BOTTOM), "tile_floor"),  # the pit's floor
    # courtyard walls and the sky
    box((-WALL, -WALL, BOTTOM - 16), (0, Y + WALL, TOP), "brick"),
    box((X, -WALL, BOTTOM - 16), (X + WALL, Y + WALL, TOP), "brick"),
    box((0, -WALL, BOTTOM - 16), (X, 0, TOP), "brick"),
    box((0, Y, BOTTOM - 16), (X, Y + WALL, TOP), "brick"),
    box((-WALL, -WALL, TOP), (X + WALL, Y + WALL, TOP + 16), "sky"),
]
water = box((PX0, PY0, BOTTOM), (PX1, PY1, SURFACE), "*water1", bottom="*waterskip")

out = ["// Game: Quake", "// Format: Valve",
       "// Written by tools/levelgen/make_pool.py (see it for the layout). 32 units a metre.",
       "{", '"classname" "worldspawn"', '"mapversion" "220"', '"message" "Pool: a pit of water to swim in"',
       '"units_per_metre" "32"', '"_wateralpha" "0.5"', '"_sunlight" "200"', '"_sun_mangle" "30 -60 0"',
       '"_sunlight2" "150"']
out += brushes
out += [water, "}"]
out += ["{", '"classname" "info_player_start"', '"origin" "64 160 24"', '"angle" "0"', "}"]
for x in (PX0 - 32, PX1 + 32):
    out += ["{", '"classname" "light"', '"origin" "%d 160 96"' % x, '"light" "300"', "}"]
text = "\n".join(out) + "\n"
if len(sys.argv) > 1:
    open(sys.argv[1], "w").write(text)
else:
    sys.stdout.write(text)
