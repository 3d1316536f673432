#!/usr/bin/python3
"""Generates the back-lit signs' test level in tests/signs/levels/ (Valve-220, 32 units a metre):

  sign_room.map  a dark room 12 x 8 m, 4 m high (worldspawn ambient 0.004: only the sign lights it),
                 with a doorway (1.5 x 2.25 m) in its west wall to a dark vestibule. Over the doorway,
                 facing east along the room, a light_sign "EXIT" hung 2 m into the room (0.3 m letters,
                 the lamp 1.5 m behind the plate, intensity 30, range 16). A pillar 0.5 x 0.5 x 2.5 m
                 stands in the beam 3 m from the sign (its shadow in the shafts and on the floor: the
                 sign's shadow map), a crate-sized block by the north wall. Game coordinates (x, z, -y):
                 plate centre (2, 2.75, -4), lamp (0.5, 2.75, -4), pillar centre x 5.25, z -3.
                 Poses ("x y z yaw pitch"): front "9 1.65 -4 90 8" (facing the sign), side
                 "5 1.65 -7.5 180 10", inside the beam "2.5 2.2 -4 -90 -15" (looking along the light),
                 behind the sign "-1.5 1.65 -4 -90 5" (in the vestibule, looking through the doorway),
                 light behind the camera "1.2 2.2 -4.3 -90 -20".

Run: /usr/bin/python3 tools/levelgen/make_sign_levels.py tests/signs/levels
Metres in Quake axes (x east, y north, z up), as make_arena.py (whose box writer this uses).
"""
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_mover_levels as movers  # noqa: E402  (its Map class and point())

box, point = movers.box, movers.point


def sign_room(path):
    # Obscura's hemisphere keys: almost no ambient (light bounced off the lit floor would be ~0.01).
    m = movers.Map("Signs: a dark room lit by a back-lit EXIT sign", "make_sign_levels.py",
                   _ambient_sky="0.004 0.004 0.005", _ambient_ground="0.003 0.003 0.003")
    # The room x 0..12, y 0..8 and the vestibule x -4..-0.5 behind its west wall, one shell.
    m.shell(-4, 0, 12, 8, 4, wall="concrete", floor="concrete", ceiling="concrete")
    # The west wall (x -0.5..0) with the doorway at y 3.25..4.75, 2.25 m high.
    m.add(box(-0.5, 0, 0, 0, 3.25, 4, "concrete"))
    m.add(box(-0.5, 4.75, 0, 0, 8, 4, "concrete"))
    m.add(box(-0.5, 3.25, 2.25, 0, 4.75, 4, "concrete"))
    # The pillar in the beam, and a block by the north wall.
    m.add(box(5, 2.75, 0, 5.5, 3.25, 2.5, "brick"))
    m.add(box(8, 6.5, 0, 9, 7.5, 1, "wood_trim"))
    # Hung 2 m in front of the doorway, tilted 12 degrees down (the light reaches the floor), the lamp
    # 1.5 m behind it: the letters' light is then (10 + 1.5)
    # / 1.5 = 7.7 times their size on the far wall, 2.3 m tall, readable across it.
    m.entity("light_sign", origin=point(2, 4, 2.75), mangle="12 0 0", text="EXIT", size="0.3", margin="0.08",
             light_distance="1.5", light="30", light_radius="0.015", range="16")
    m.entity("info_player_start", origin=point(9, 4, 0.75), angle="180")
    m.write(path, ["A dark room and a back-lit sign (see the script's docstring)."])


def main(args):
    if len(args) != 1:
        print("usage: make_sign_levels.py OUT_DIR", file=sys.stderr)
        return 2
    sign_room(os.path.join(args[0], "sign_room.map"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
