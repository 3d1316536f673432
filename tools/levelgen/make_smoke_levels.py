#!/usr/bin/python3
"""Generates the smoke's render-test level in tests/smoke/levels/ (Valve-220, 32 units a metre):

  sun_tower.map  an open 64 x 64 m floor under a sun from the west, 50 degrees up, and a 40 m
                 tower (1 m thick, 20 m long) at x = -15..-14 m, y = 0..20 m (Quake axes; the
                 game's z = -y). A cloud released at the origin fills a 16 m box (x -8..8): the
                 tower is outside it, so the solver's own transmittance towards the sun does not
                 see it, but it shadows the north half of the box (y > 0, the game's z < 0) from
                 the sun: the rays towards the sun from every point of that half with x <= 8 m and
                 height <= 8 m meet the tower's west face below 40 m (22 m west, rising 22 x
                 tan 50 = 26.2 m, so at most 34.2 m). tests/smoke/smoke_render_test.cpp.

Run: /usr/bin/python3 tools/levelgen/make_smoke_levels.py tests/smoke/levels
Metres in Quake axes (x east, y north, z up), as make_arena.py (whose box writer this uses).
"""
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_mover_levels as movers  # noqa: E402  (its Map writer)

box, point = movers.box, movers.point


def sun_tower(path):
    # _sun_mangle is "yaw pitch roll" the way the light travels: yaw 0 = east, pitch -50 = down
    # 50 degrees, so the sun stands in the west. _sunlight 220 and the ambients as the arena's.
    m = movers.Map("Smoke under a tower's shadow", generator="make_smoke_levels.py",
                   _sunlight="220", _sun_mangle="0 -50 0", _sunlight_color="255 240 220",
                   _ambient_sky="0.41098039 0.44480392 0.53", _ambient_ground="0.16 0.14 0.12")
    m.add(box(-32, -32, -0.5, 32, 32, 0, "concrete"))
    m.add(box(-15, 0, 0, -14, 20, 40, "brick"))
    m.entity("info_player_start", origin=point(24, 0, 1), angle="180")
    m.write(path, ["A floor, a sun from the west 50 degrees up, and a 40 m tower west of a 16 m smoke box:",
                   "it shadows the box's north half (tests/smoke/smoke_render_test.cpp)."])


def main(out_dir):
    os.makedirs(out_dir, exist_ok=True)
    sun_tower(os.path.join(out_dir, "sun_tower.map"))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/smoke/levels")
