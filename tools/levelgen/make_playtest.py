#!/usr/bin/python3
"""Generates the start-to-exit playtest levels in tests/sim/levels/ (Valve-220, 32 units a metre):

  playtest.map      every mover and trigger class on one straight walk north, then a teleport
                    into a second room and its exit. Holding forward from the start plays it
                    through (tests/replay/scripts/playtest.replay):
                      hall:   trigger_once (a message) opens a rising func_door; a hint brush and a
                              deathmatch-only func_wall (spawnflags 1792) across the way are not
                              there; a trigger_hurt (dmg 10); a func_button in the way is pressed by
                              walking into it and slides a func_door aside;
                      climb:  a func_plat up to a 2 m ledge, a trigger_push forward, a
                              trigger_multiple (a message), a trigger_teleport;
                      room:   a trigger_once and a trigger_secret each count down a trigger_counter
                              (count 2), whose trigger_relay (delay 0.5 s, a message) opens a
                              func_door_secret; a func_train runs overhead; a trigger_changelevel
                              names playtest_end.
  playtest_end.map  the next level: one lit room.

Run: /usr/bin/python3 tools/levelgen/make_playtest.py tests/sim/levels
Metres in Quake axes (x east, y north, z up), as make_mover_levels.py (whose Map this uses).
"""
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_mover_levels as movers  # noqa: E402

Map, box, point = movers.Map, movers.box, movers.point

# The walk: x 2.75 (a 1 m wide player brushes the button at x 3), from y 1 north.
PATH_X = 2.75


def hall(m):
    m.shell(0, 0, 4, 38, 4)
    m.entity("info_player_start", origin=point(PATH_X, 1, 0.75), angle="90")
    m.entity("trigger_once", [box(0, 2, 0, 4, 3, 3, "trigger")], target="door_a", message="Playtest: every mover and trigger")
    # A wall with a 2 m doorway (x 1.5..3.5), its door rising 3 m - 8 u at 100 u/s once the trigger fires.
    m.add(box(0, 6, 0, 1.5, 6.5, 4, "brick"))
    m.add(box(3.5, 6, 0, 4, 6.5, 4, "brick"))
    m.add(box(1.5, 6, 3, 3.5, 6.5, 4, "brick"))
    m.entity("func_door", [box(1.5, 6, 0, 3.5, 6.5, 3, "metal_door")], angle="-1", targetname="door_a", wait="-1")
    # Neither is there to walk into: a hint brush (ericw qbsp: not drawn, not solid) and a wall
    # flagged out of every skill (E1M1's deathmatch-only walls).
    m.add(box(0, 8, 0, 4, 8.25, 4, "hint"))
    m.entity("func_wall", [box(0, 9, 0, 4, 9.5, 4, "brick")], spawnflags="1792")
    m.entity("trigger_hurt", [box(0, 10, 0, 4, 11, 3, "trigger")], dmg="10")
    # The button stands 1 m out of the east wall in the way; walking into it presses it 1 m - 4 u east.
    m.entity("func_button", [box(3, 13, 0.25, 4, 13.5, 1.5, "button_red")], angle="0", target="door_b")
    m.add(box(0, 16, 0, 1.5, 16.5, 4, "brick"))
    m.add(box(3.5, 16, 0, 4, 16.5, 4, "brick"))
    m.add(box(1.5, 16, 3, 3.5, 16.5, 4, "brick"))
    m.entity("func_door", [box(1.5, 16, 0, 3.5, 16.5, 3, "metal_door")], angle="180", targetname="door_b", wait="-1")


def climb(m):
    # The plat (built at the top, 2 m) rests 2 m - 8 u lower; stood on, it rises to the ledge.
    m.entity("func_plat", [box(1.5, 19, 0, 4, 22, 2, "metal_floor")])
    m.add(box(0, 22, 0, 4, 38, 2, "concrete"))
    m.entity("trigger_push", [box(0, 25, 2, 4, 26, 4, "trigger")], angle="90", speed="30")
    m.entity("trigger_multiple", [box(0, 28, 2, 4, 29, 4, "trigger")], message="Almost there", wait="2")
    m.add(box(1.5, 33, 2, 4, 34, 2 + 1 / 32, "tele_pad"))
    m.entity("trigger_teleport", [box(0, 33, 2, 4, 34, 4, "trigger")], target="room")
    m.entity("light", origin=point(2, 4, 3.5), light="300", _color="1 0.92 0.8")
    m.entity("light", origin=point(2, 13, 3.5), light="300", _color="0.9 0.95 1")
    m.entity("light", origin=point(2, 28, 3.75), light="260", _color="1 1 0.9")


def room(m):
    m.shell(8, 0, 14, 14, 4)
    m.entity("info_teleport_destination", origin=point(8 + PATH_X, 1, 0), angle="90", targetname="room")
    m.entity("trigger_once", [box(8, 3, 0, 14, 4, 3, "trigger")], target="count2")
    m.entity("trigger_secret", [box(8, 5, 0, 14, 6, 3, "trigger")], target="count2", message="A secret area")
    m.entity("trigger_counter", targetname="count2", count="2", target="relay1", spawnflags="1")
    m.entity("trigger_relay", targetname="relay1", delay="0.5", message="The exit opens", target="door_exit")
    # The exit: a secret door in a 2 m doorway (x 9.5..11.5 + 8 keeps the walk inside it) slides east.
    m.add(box(8, 9, 0, 9.5, 9.5, 4, "brick"))
    m.add(box(11.5, 9, 0, 14, 9.5, 4, "brick"))
    m.add(box(9.5, 9, 3, 11.5, 9.5, 4, "brick"))
    m.entity("func_door_secret", [box(9.5, 9, 0, 11.5, 9.5, 3, "metal_door")], angle="90", targetname="door_exit")
    # Overhead, out of the way: a train between two corners.
    m.entity("path_corner", origin=point(8.5, 12.5, 3.25), targetname="p1", target="p2")
    m.entity("path_corner", origin=point(12.5, 12.5, 3.25), targetname="p2", target="p1")
    m.entity("func_train", [box(8.5, 12.5, 3.25, 9.5, 13, 3.5, "metal_floor")], target="p1", speed="64")
    m.entity("trigger_changelevel", [box(8, 12, 0, 14, 13, 3, "trigger")], map="playtest_end")
    m.entity("light", origin=point(11, 4, 3.5), light="300", _color="0.95 0.9 1")
    m.entity("light", origin=point(11, 11.5, 2.75), light="260", _color="1 0.9 0.8")


def playtest(path):
    m = Map("Playtest: every mover and trigger, start to exit", generator="make_playtest.py")
    hall(m)
    climb(m)
    room(m)
    m.write(path, ["Every mover and trigger class on one walk to a trigger_changelevel (see the script's docstring)."])


def playtest_end(path):
    m = Map("Playtest: the next level", generator="make_playtest.py")
    m.shell(0, 0, 6, 6, 3)
    m.entity("info_player_start", origin=point(3, 1, 0.75), angle="90")
    m.entity("light", origin=point(3, 3, 2.5), light="300")
    m.write(path, ["The level playtest.map's trigger_changelevel names."])


def main(args):
    if len(args) != 1:
        print("usage: make_playtest.py OUT_DIR", file=sys.stderr)
        return 2
    playtest(os.path.join(args[0], "playtest.map"))
    playtest_end(os.path.join(args[0], "playtest_end.map"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
