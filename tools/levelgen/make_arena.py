#!/usr/bin/python3
"""Generates media/levels/arena.map, Obscura's default level, as a Valve-220 Quake map.

Run: /usr/bin/python3 tools/levelgen/make_arena.py media/levels/arena.map   (or no argument: stdout)
     /usr/bin/python3 tools/levelgen/make_arena.py --plan   (the ASCII top view in the README)
Everything below is in metres (Quake axes: x east, y north, z up); the writer converts to map
units at 32 units per metre. See media/levels/README.md for the plan.

Format: Valve-220 as TrenchBroom writes it (one face per line,
`( x y z ) ( x y z ) ( x y z ) TEXTURE [ ux uy uz uoff ] [ vx vy vz voff ] rot sx sy`); the three
points of a face are ordered so that normalize(cross(p3 - p1, p2 - p1)) points out of the brush.
The self-check at the end (levelcheck.py) proves every brush closed and outward, finds overlaps,
leaks and entities stuck in walls, and refuses to write a map that fails.
"""
import math
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the sources
from levelcheck import Brush, LevelError, check_level  # noqa: E402

UNITS = 32  # map units per metre (worldspawn "units_per_metre")

brushes = []   # worldspawn brushes: lists of faces (see face())
entities = []  # point entities: dicts of keys in file order


def u(m):
    """Metres -> map units (integers: every coordinate here is a multiple of 1/32 m)."""
    v = round(m * UNITS)
    assert abs(v - m * UNITS) < 1e-6, f"{m} m is not on the 1/32 m grid"
    return v


def axes(normal):
    """Texture axes by face orientation (as TrenchBroom's defaults)."""
    if normal in ("+z", "-z"):
        return "[ 1 0 0 0 ] [ 0 -1 0 0 ]"
    if normal in ("+x", "-x"):
        return "[ 0 1 0 0 ] [ 0 0 -1 0 ]"
    return "[ 1 0 0 0 ] [ 0 0 -1 0 ]"


def face(p1, p2, p3, tex, normal):
    """One face: three points in metres (converted to units here), texture, orientation tag."""
    return (tuple(tuple(u(c) for c in p) for p in (p1, p2, p3)), tex, normal)


def face_line(f):
    pts, tex, normal = f
    return " ".join(f"( {a} {b} {c} )" for a, b, c in pts) + f" {tex} {axes(normal)} 0 1 1"


def box(x0, y0, z0, x1, y1, z1, tex, top=None, bottom=None):
    """An axis-aligned box; the three points of each face wind so the normal points out."""
    assert x1 > x0 and y1 > y0 and z1 > z0, (x0, y0, z0, x1, y1, z1)
    e = 1.0 / UNITS
    top = top or tex
    bottom = bottom or tex
    return [
        face((x0, y0, z0), (x0, y0 + e, z0), (x0, y0, z0 + e), tex, "-x"),
        face((x0, y0, z0), (x0, y0, z0 + e), (x0 + e, y0, z0), tex, "-y"),
        face((x0, y0, z0), (x0 + e, y0, z0), (x0, y0 + e, z0), bottom, "-z"),
        face((x1, y1, z1), (x1, y1 + e, z1), (x1 + e, y1, z1), top, "+z"),
        face((x1, y1, z1), (x1 + e, y1, z1), (x1, y1, z1 + e), tex, "+y"),
        face((x1, y1, z1), (x1, y1, z1 + e), (x1, y1 + e, z1), tex, "+x"),
    ]


MAX_RAMP_DEGREES = 30  # the level brief's limit; the player controller is tested walking up 30 degrees


def ramp_x(x0, x1, y0, y1, zb, z0, z1, tex):
    """A ramp rising along +x from height z0 at x0 to z1 at x1, bottom at zb: a 5-face wedge when
    it starts at its bottom (z0 == zb), else a 6-face box with a sloped top."""
    assert zb <= z0 < z1, (zb, z0, z1)
    assert (z1 - z0) <= (x1 - x0) * math.tan(math.radians(MAX_RAMP_DEGREES)), f"ramp steeper than {MAX_RAMP_DEGREES} degrees"
    faces = [f for f in box(x0, y0, zb, x1, y1, z1, tex)
             if f[2] != "+z" and not (f[2] == "-x" and z0 == zb)]
    # Slope plane through (x0, y0, z0), (x0, y1, z0), (x1, y0, z1); normal up and towards -x.
    faces.append(face((x0, y0, z0), (x0, y1, z0), (x1, y0, z1), tex, "+z"))
    return faces


def add(b):
    brushes.append(b)


def stairs_y(x0, x1, y0, z0, steps, rise, run, tex):
    """Steps climbing towards +y from (y0, z0): each `rise` high and `run` deep."""
    assert rise <= 18 / 32, "the player steps up 18 Quake units (0.5625 m) at most (game/sim/README.md)"
    for i in range(steps):
        add(box(x0, y0 + i * run, z0, x1, y0 + (i + 1) * run, z0 + (i + 1) * rise, tex))


def wall_with_doors(axis, fixed, a0, a1, z0, z1, thick, tex, doors):
    """A wall along `axis` ('x' or 'y') from a0 to a1 at `fixed` (its inner face), `thick` metres
    thick outwards (sign of thick says which side), split around doors [(start, width, height)]."""
    segs, pos = [], a0
    for start, width, height in sorted(doors):
        if start > pos:
            segs.append((pos, start, z0, z1))
        segs.append((start, start + width, z0 + height, z1))  # lintel
        pos = start + width
    if pos < a1:
        segs.append((pos, a1, z0, z1))
    f0, f1 = sorted((fixed, fixed + thick))
    for s0, s1, zb, zt in segs:
        if zt - zb <= 0 or s1 - s0 <= 0:
            continue
        if axis == "x":
            add(box(s0, f0, zb, s1, f1, zt, tex))
        else:
            add(box(f0, s0, zb, f1, s1, zt, tex))


def room(x0, y0, x1, y1, height, wall, floor, ceiling, doors=None, t=0.5):
    """An enclosed room: floor slab, four walls (doors per side: 'n','s','e','w'), ceiling."""
    doors = doors or {}
    add(box(x0 - t, y0 - t, -0.5, x1 + t, y1 + t, 0, "concrete", top=floor))
    wall_with_doors("x", y0, x0 - t, x1 + t, 0, height, -t, wall, doors.get("s", []))
    wall_with_doors("x", y1, x0 - t, x1 + t, 0, height, t, wall, doors.get("n", []))
    wall_with_doors("y", x0, y0, y1, 0, height, -t, wall, doors.get("w", []))
    wall_with_doors("y", x1, y0, y1, 0, height, t, wall, doors.get("e", []))
    if ceiling:
        add(box(x0 - t, y0 - t, height, x1 + t, y1 + t, height + t, ceiling))


def entity(classname, **keys):
    entities.append({"classname": classname, **keys})


def point(x, y, z):
    return f"{u(x)} {u(y)} {u(z)}"


# Doorways: 1.5 m wide, 2.25 m high (the player is 1.8 m; 72 units keeps the grid integral). The
# two corridor mouths of the 2 m corridor between room A and the courtyard are the corridor's width.
DOOR_W, DOOR_H = 1.5, 2.25
SIGN_DOOR_Y = 49.0  # the doorway east out of room B, to the dark sign room C (y 49-50.5)

# --- Courtyard: 24 x 24 m, open to the sky, 12 m brick walls. The east wall's inner face is the
# free wall for the back-lit sign.
CX0, CY0, CX1, CY1 = 20, 20, 44, 44
add(box(CX0 - 0.5, CY0 - 0.5, -0.5, CX1 + 0.5, CY1 + 0.5, 0, "concrete", top="stone"))
wall_with_doors("x", CY0, CX0 - 0.5, CX1 + 0.5, 0, 12, -0.5, "brick", [(30.5, DOOR_W, DOOR_H)])  # south: to the range
wall_with_doors("x", CY1, CX0 - 0.5, CX1 + 0.5, 0, 12, 0.5, "brick", [])
wall_with_doors("y", CX0, CY0, CY1, 0, 12, -0.5, "brick", [(27.25, 2.0, DOOR_H)])  # west: to room A
wall_with_doors("y", CX1, CY0, CY1, 0, 12, 0.5, "brick", [])  # east: the sign wall
# Thin pillars (0.25 m square, 5 m tall): the classic SSAO stress case.
for i in range(4):
    add(box(23 + i * 1.5, 36, 0, 23.25 + i * 1.5, 36.25, 5, "stone"))
# A ramp along the north wall up to a 3 m walkway in the north-east corner (3 m over 12 m: 14 deg).
add(ramp_x(28, 40, 41, 44, 0, 0, 3, "concrete"))
add(box(40, 40, 0, 44, 44, 3, "concrete"))
# A low wall to take cover behind.
add(box(30, 28, 0, 34, 28.5, 1.125, "concrete"))

# --- Corridor west from the courtyard to room A: 3 m long, 2 m wide (as its doorways), 3.5 m high.
# (Everything stops at x = 19.5, where the courtyard wall begins: no coplanar overlaps.)
add(box(16.5, 27.25, -0.5, 19.5, 29.25, 0, "concrete", top="tile_floor"))
add(box(16.5, 26.75, 0, 19.5, 27.25, 3.5, "plaster"))
add(box(16.5, 29.25, 0, 19.5, 29.75, 3.5, "plaster"))
add(box(16.5, 26.75, 3.5, 19.5, 29.75, 4.0, "plaster"))

# --- Room A: 14 x 12 m, 4 m high, doors east (corridor) and north (to room B).
room(2, 22, 16, 34, 4, "plaster", "tile_floor", "plaster",
     doors={"e": [(27.25, 2.0, DOOR_H)], "n": [(8.0, DOOR_W, DOOR_H)]})
for i in range(3):  # crates in room A
    entity("prop_crate", origin=point(5 + i * 1.25, 25, 0), size="0.75")

# --- Corridor north from room A to room B: 2.5 m wide, 3 m long, 3.5 m high.
add(box(7.5, 34.5, -0.5, 10, 37.5, 0, "concrete", top="tile_floor"))
add(box(7, 34.5, 0, 7.5, 37.5, 3.5, "plaster"))
add(box(10, 34.5, 0, 10.5, 37.5, 3.5, "plaster"))
add(box(7, 34.5, 3.5, 10.5, 37.5, 4.0, "plaster"))

# --- Room B: 14 x 14 m, 6 m high, with stairs (10 steps of 0.25 m rise, 0.375 m run: 12 units, the
# first whole-unit tread at least 0.35 m deep) up to a 2.5 m mezzanine.
room(2, 38, 16, 52, 6, "plaster", "wood_trim", "plaster",
     doors={"s": [(8.0, DOOR_W, DOOR_H)], "e": [(SIGN_DOOR_Y, DOOR_W, DOOR_H)]})
stairs_y(12, 15.5, 40, 0, 10, 0.25, 0.375, "wood_trim")
add(box(2, 43.75, 2.25, 16, 52, 2.5, "wood_trim"))  # mezzanine floor
add(box(2, 43.75, 0, 2.5, 44.25, 2.25, "metal_floor"))  # its supports
add(box(8, 43.75, 0, 8.5, 44.25, 2.25, "metal_floor"))
add(box(2, 43.5, 2.5, 11.5, 43.75, 3.5, "metal_floor"))  # railing
entity("prop_crate", origin=point(4, 48, 2.5), size="0.75")
# Painted signs (decal_sign, engine_ext/decals: distance-field decals projected onto the plaster):
# on walls no replay capture looked at before them. "ROOM B" on the south wall by the door, facing
# in, its centre at the standing eye's height (tests/replay/scripts/decal_signs.replay looks at
# it from 0.4 m); "UP" over the stairs; "EXIT" on the west wall, glowing.
entity("decal_sign", origin=point(5, 38, 1.625), angle="90", text="ROOM B", size="1.2",
       _color="0.15 0.2 0.45", style="smooth shadow")
entity("decal_sign", origin=point(16, 42, 3.25), angle="180", text="UP", size="0.8",
       _color="0.7 0.12 0.05", style="smooth outline")
entity("decal_sign", origin=point(2, 40.5, 1.625), angle="0", text="EXIT", size="0.8",
       _color="0.1 0.6 0.15", style="smooth glow")

# --- Room C, the dark sign room (issue 15, engine_ext/signs): x 22.5-34.5, y 45.5-55.5 (12 x 10 m),
# 4 m high, concrete, behind the courtyard's north wall; no lamp of its own, no sky (no lamp's reach
# gets into it either: point lights cast no shadows here, so it lies over 13 m from room B's, whose
# reach is 6.9 and 10 m; tests/signs checks it). Reached from room B through a doorway in room B's
# east wall under the mezzanine (y 49-50.5) and a 5.5 m corridor (x 16.5-22, 3 m high). Its only
# light is the back-lit `light_sign` "EXIT" before the doorway in its west wall, facing east along
# the room and 10 degrees down: the plate's centre at (24.09375, 49.75, 2.75) (1.6 m in front of the west
# wall, its bottom edge over the doorway's 2.25 m top), the lamp 1.2 m behind it, 0.4 m from the wall
# (range 16 so the light reaches the far wall). In the game's world (x, z, -y): plate
# (24.09375, 2.75, -49.75), lamp (22.912, 2.958, -49.75). Camera
# poses (--start-pose / a replay's `start`, "x y z yaw pitch"): looking back at the sign across the
# room "32 1.65 -52 104 -5"; from beside the doorway along the light to the far wall "24 1.65 -48 -90 -8".
SIGN_ROOM = dict(x0=22.5, y0=45.5, x1=34.5, y1=55.5, height=4)
add(box(16.5, SIGN_DOOR_Y, -0.5, 22, SIGN_DOOR_Y + DOOR_W, 0, "concrete"))             # corridor floor
add(box(16.5, SIGN_DOOR_Y - 0.5, 0, 22, SIGN_DOOR_Y, 3, "concrete"))                   # its walls
add(box(16.5, SIGN_DOOR_Y + DOOR_W, 0, 22, SIGN_DOOR_Y + DOOR_W + 0.5, 3, "concrete"))
add(box(16.5, SIGN_DOOR_Y - 0.5, 3, 22, SIGN_DOOR_Y + DOOR_W + 0.5, 3.5, "concrete"))  # its ceiling
room(SIGN_ROOM["x0"], SIGN_ROOM["y0"], SIGN_ROOM["x1"], SIGN_ROOM["y1"], SIGN_ROOM["height"], "concrete", "concrete",
     "concrete", doors={"w": [(SIGN_DOOR_Y, DOOR_W, DOOR_H)]})
# Hung 1.6 m in front of the doorway and tilted 10 degrees down, its lamp 1.2 m behind it (0.4 m
# from the wall): the letters' light on the far wall is (1.2 + 10.4) / 1.2 = 9.7 times their
# 0.25 m, 2.4 m tall, readable; intensity 40 (chosen before the room's env_ambient below, over the
# full sky ambient; kept: the letters on the far wall and the shafts stay bright in the dark room).
entity("light_sign", origin=point(SIGN_ROOM["x0"] + 1.59375, SIGN_DOOR_Y + DOOR_W / 2, 2.75), mangle="10 0 0", text="EXIT",
       size="0.25", margin="0.08", light_distance="1.2", light="40", light_radius="0.015", range="16")
# The sky's ambient does not get into room C: an env_ambient (engine_ext/map/README.md) scales it to
# 0.1 there. Its box reaches 0.25 m into the walls, floor and ceiling slabs (0.5 m thick) and fades
# over 0.4 m centred on its faces, so the room's own surfaces are fully inside (0.25 m in, past the
# 0.2 m half-fade) and the far faces of its walls (0.25 m out: the courtyard's north wall) fully
# outside; the doorway's light fades over the corridor's last 0.45 m.
AMBIENT_AREAS = [({"ambient": "0.1", "blend": "0.4"},
                  box(SIGN_ROOM["x0"] - 0.25, SIGN_ROOM["y0"] - 0.25, -0.25, SIGN_ROOM["x1"] + 0.25, SIGN_ROOM["y1"] + 0.25,
                      SIGN_ROOM["height"] + 0.25, "trigger"))]

# --- Firing range: 42 x 6 m, 5 m high, reached from the courtyard through a corridor.
room(10, 3, 52, 9, 5, "concrete", "concrete", "concrete", doors={"n": [(30.5, DOOR_W, DOOR_H)]})
add(box(14, 3, 0, 14.5, 7.5, 1.125, "wood_trim"))  # the shooter's booth counter
add(box(14, 3, 2.5, 14.5, 9, 5, "concrete"))      # booth front wall above the counter
# Corridor from the courtyard's south door to the range: 11 m, 2.5 m wide (the smoke-test corridor).
add(box(30, 9.5, -0.5, 32.5, 19.5, 0, "concrete", top="metal_floor"))
add(box(29.5, 9.5, 0, 30, 19.5, 3, "concrete"))
add(box(32.5, 9.5, 0, 33, 19.5, 3, "concrete"))
add(box(29.5, 9.5, 3, 33, 19.5, 3.5, "concrete"))
# Clip brush: an invisible 1 m railing along the open south edge of the courtyard walkway (players
# do not walk off the 3 m ledge; bullets pass over the booth counter, which stays unclipped).
add(box(40, 39.75, 3, 44, 40, 4, "clip"))

# --- Sky box: the whole level sits inside it (the map is sealed).
S0, S1, TOP = -2, 62, 16
add(box(S0, S0, -1.5, S1, S1, -1, "sky"))
add(box(S0, S0, TOP, S1, S1, TOP + 0.5, "sky"))
add(box(S0 - 0.5, S0, -1.5, S0, S1, TOP + 0.5, "sky"))
add(box(S1, S0, -1.5, S1 + 0.5, S1, TOP + 0.5, "sky"))
add(box(S0, S0 - 0.5, -1.5, S1, S0, TOP + 0.5, "sky"))
add(box(S0, S1, -1.5, S1, S1 + 0.5, TOP + 0.5, "sky"))

# A trigger volume (invisible, not solid) at the range end of the smoke-test corridor, to exercise
# the brush-entity classes.
TRIGGER = box(30, 9.5, 0, 32.5, 10.5, 2.5, "trigger")

# --- Point entities. A Quake player origin is the body centre, 24 units (0.75 m) above the feet.
entity("info_player_start", origin=point(26, 24, 0.75), angle="135")  # courtyard, facing the west door
# The sign: on the east wall's inner face (x = 44), centred 4 m up, facing west into the courtyard.
SIGN = dict(x=44, y=32, z=4, width=5, height=1.5)
entity("info_sign", origin=point(SIGN["x"], SIGN["y"], SIGN["z"]), angle="180", text="OBSCURA",
       width=str(SIGN["width"]), height=str(SIGN["height"]))
# The arena's lamps keep the look they were tuned with before Quake's falloff was read: Lambert's
# cosine (`_anglescale` 1, Quake's default is 0.5) and Quake's linear falloff squared (Obscura's
# `_falloff_exponent` 2), which reaches 0 at the same `light` units but fades smoothly.
LAMP = dict(_anglescale="1", _falloff_exponent="2")
for x, y, z, l in [(6, 25, 3.5, 280), (12, 31, 3.5, 280), (9, 45, 5.5, 320), (9, 50, 2, 220),
                   (18, 28.25, 3, 200), (8.75, 36, 3, 200), (31.25, 14.5, 2.5, 220), (31.25, 22, 2.5, 200)]:
    entity("light", origin=point(x, y, z), light=str(l), _color="1 0.92 0.8", **LAMP)  # warm indoor lamps
for x in (16, 26, 36, 46):
    entity("light", origin=point(x, 6, 4.5), light="300", _color="0.95 0.97 1", **LAMP)  # cool range strip lights
# The firing range: the shooter stands behind the booth counter (x < 14) looking east. Pop-up boards at
# 10, 20 and 30 m (they fall when shot three times and rise after 3 s), two boards sliding across
# the range at 15 and 25 m, all facing west (angle 180). Props to knock over by the booth.
for x, y in [(24, 6), (34, 4.5), (44, 7.5)]:
    entity("target_popup", origin=point(x, y, 0), angle="180", width="0.6", height="1.6", reset="3")
for x, speed in [(29, "1.5"), (39, "2.5")]:
    entity("target_moving", origin=point(x, 6, 0), angle="180", width="0.6", height="1.6", distance="4", speed=speed)
for x, y in [(16.5, 8.25), (17.375, 8.25), (20, 7.5)]:
    entity("prop_barrel", origin=point(x, y, 0), radius="0.3", height="0.9")
entity("prop_crate", origin=point(18.5, 4.25, 0), size="0.75")
# A second spawn point in the courtyard's south-east, clear of the sign's 8 m apron.
entity("info_player_deathmatch", origin=point(40, 24, 0.75), angle="90")

WORLDSPAWN = [("classname", "worldspawn"), ("mapversion", "220"), ("message", "Obscura arena"),
              ("units_per_metre", str(UNITS)),
              # Sun from the north-north-west (travelling towards yaw -60), 55 degrees up: it lights
              # the sign wall (facing west) and lets the north wall shade part of the courtyard.
              ("_sunlight", "220"), ("_sun_mangle", "-60 -55 0"), ("_sunlight_color", "255 240 220"),
              ("_sunlight2", "120"), ("_sunlight2_color", "200 215 255"),  # bluish sky-dome fill
              # The ambient hemisphere (Obscura's keys, linear irradiance from above and below) as
              # the arena was tuned: the engine's old default hemisphere, halved from above, plus the
              # dome (200 215 255)/255 x 120/375. Without them a level with lights gets Quake's
              # dark ambient (engine_ext/map/README.md, "Lighting keys").
              ("_ambient_sky", "0.41098039 0.44480392 0.53"), ("_ambient_ground", "0.16 0.14 0.12")]


def write(out):
    out.write("// Game: Quake\n// Format: Valve\n// Generated by tools/levelgen/make_arena.py: edit the script, not this file.\n")
    out.write("// entity 0\n{\n")
    for k, v in WORLDSPAWN:
        out.write(f'"{k}" "{v}"\n')
    for i, b in enumerate(brushes):
        out.write(f"// brush {i}\n{{\n" + "\n".join(face_line(f) for f in b) + "\n}\n")
    out.write("}\n")
    out.write('// entity 1\n{\n"classname" "trigger_multiple"\n{\n' + "\n".join(face_line(f) for f in TRIGGER) + "\n}\n}\n")
    for i, e in enumerate(entities):
        out.write(f"// entity {i + 2}\n{{\n" + "".join(f'"{k}" "{v}"\n' for k, v in e.items()) + "}\n")
    # Brush entities after the point entities (their lines, which messages name, stay where they were).
    for i, (keys, b) in enumerate(AMBIENT_AREAS):
        out.write(f"// entity {len(entities) + 2 + i}\n{{\n\"classname\" \"env_ambient\"\n" +
                  "".join(f'"{k}" "{v}"\n' for k, v in keys.items()) + "{\n" + "\n".join(face_line(f) for f in b) + "\n}\n}\n")


def plan(out, step_x=1, step_y=1, z=1):
    """Top view in a band at height z..z+0.5 m, one character per step_x by step_y metres:
    '#' walls (taller than the band), '-' low things (counter, cover, stair steps), 'c' clip, and
    the point entities on top: P player start, D deathmatch start, S sign, x crates, o barrels,
    T pop-up targets, M moving targets (the middle of their track), * lights, E the back-lit sign."""
    solids = [Brush(b, "") for b in brushes if b[0][1] != "sky"]
    marks = {"info_player_start": "P", "info_player_deathmatch": "D", "info_sign": "S", "prop_crate": "x",
             "prop_barrel": "o", "target_popup": "T", "target_moving": "M", "light": "*", "light_sign": "E"}
    cols, rows = 55, 57
    grid = [[" "] * cols for _ in range(rows)]
    for r in range(rows):
        for c in range(cols):
            lo = (c * step_x * UNITS, r * step_y * UNITS, z * UNITS)
            hi = ((c + 1) * step_x * UNITS, (r + 1) * step_y * UNITS, z * UNITS + UNITS // 2)
            for b in solids:
                if b.overlaps_box(lo, hi):
                    grid[r][c] = "c" if "clip" in b.textures else ("-" if b.hi[2] <= hi[2] else "#")
    for e in entities:
        x, y, _ = (int(v) / UNITS for v in e["origin"].split())
        c, r = min(int(x / step_x), cols - 1), min(int(y / step_y), rows - 1)
        grid[r][c] = marks.get(e["classname"], "?")
    for r in reversed(range(rows)):  # north up; each row is labelled with its southern edge
        if "".join(grid[r]).strip():
            out.write(f"{r * step_y:3d} {''.join(grid[r]).rstrip()}\n")
    out.write("    " + "".join(f"{c:<10d}" for c in range(0, cols, 10)) + "\n")


def main(args):
    if args == ["--plan"]:
        plan(sys.stdout)
        return 0
    if len(args) > 1 or (args and args[0].startswith("-")):
        print("usage: make_arena.py [OUT.map] | --plan", file=sys.stderr)
        return 2
    try:
        report = check_level(brushes, [TRIGGER], entities, UNITS, sign=SIGN,
                             required_textures={"brick", "concrete", "plaster", "tile_floor", "metal_floor",
                                                "wood_trim", "stone", "sky", "clip"})
    except LevelError as e:
        print(f"make_arena: check failed, nothing written: {e}", file=sys.stderr)
        return 1
    if args:
        with open(args[0], "w") as out:
            write(out)
    else:
        write(sys.stdout)
    print(f"make_arena: {len(brushes) + 1} brushes ({len(brushes)} world + 1 trigger), "
          f"{len(entities) + 2} entities; {report}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
