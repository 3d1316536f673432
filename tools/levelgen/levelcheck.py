"""Self-check for generated levels (used by make_arena.py before it writes the map).

Exact arithmetic on the integer map-unit coordinates (fractions.Fraction), so no epsilon decides
anything. A face is (points, texture, orientation tag) with three integer points whose plane
normal normalize(cross(p3 - p1, p2 - p1)) must point out of the brush (the map compiler's
convention). Checks, each failing with a message naming the brush or entity:
  - every brush is a box (6 faces) or a wedge (5), closed and convex: each face's plane carries a
    real polygon (>= 3 vertices), the brush has volume, its centre lies behind every plane (so the
    points wind outwards) and each face's orientation tag (which picked its texture axes) agrees
    with its normal;
  - no two brushes overlap with positive volume (touching is fine);
  - the level is sealed: a flood fill from every point entity through the empty space never
    reaches the outside (the grid is the brushes' own coordinates, so the fill is exact for boxes);
  - point entities sit in empty space (inside the sky box: else the flood fill leaks); the player start stands on a floor
    with headroom; crates rest on a floor; lights have sane values;
  - the sign has a wall behind it (6 x 4 m) and 8 m of empty space in front;
  - the required textures are all used and the brush count is moderate.
"""
from bisect import bisect_left
from collections import deque
from fractions import Fraction
from itertools import combinations

PLAYER_HALF_WIDTH = 16  # units: Quake's player hull is 32 x 32 x 56
PLAYER_HEIGHT = 56
PLAYER_ORIGIN_ABOVE_FEET = 24
SIGN_WALL = (6, 4)      # metres of plain wall the sign needs (width, height)
SIGN_APRON = 8          # metres of empty space in front of the sign
MAX_BRUSHES = 400       # "moderate": keeps the level quick to compile and to voxelise


class LevelError(Exception):
    pass


def fail(msg):
    raise LevelError(msg)


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def plane(f):
    """(n, d): outward normal (integers, not unit) and offset; inside is dot(n, p) < d."""
    p1, p2, p3 = f[0]
    n = cross(sub(p3, p1), sub(p2, p1))
    if n == (0, 0, 0):
        fail(f"face {f} has collinear points")
    return n, dot(n, p1)


def vertices(planes):
    """Corners of the convex region dot(n, p) <= d for all planes (exact, deduplicated)."""
    out = set()
    for (n1, d1), (n2, d2), (n3, d3) in combinations(planes, 3):
        c23, c31, c12 = cross(n2, n3), cross(n3, n1), cross(n1, n2)
        det = dot(n1, c23)
        if det == 0:
            continue
        p = tuple(Fraction(d1 * c23[i] + d2 * c31[i] + d3 * c12[i], det) for i in range(3))
        if all(dot(n, p) <= d for n, d in planes):
            out.add(p)
    return out


def has_volume(points):
    pts = list(points)
    if len(pts) < 4:
        return False
    o = pts[0]
    for a, b, c in combinations(pts[1:], 3):
        if dot(sub(a, o), cross(sub(b, o), sub(c, o))) != 0:
            return True
    return False


TAGS = {"+x": (0, 1), "-x": (0, -1), "+y": (1, 1), "-y": (1, -1), "+z": (2, 1), "-z": (2, -1)}


class Brush:
    def __init__(self, faces, name):
        self.name, self.faces = name, faces
        self.textures = {f[1] for f in faces}
        self.solid = not ({"trigger"} & self.textures)
        self.seals = self.solid and "clip" not in self.textures  # clip does not seal (as in qbsp)
        if len(faces) not in (5, 6):
            fail(f"{name}: {len(faces)} faces (a box has 6, a wedge 5)")
        self.planes = [plane(f) for f in faces]
        self.verts = vertices(self.planes)
        if not has_volume(self.verts):
            fail(f"{name}: no volume (open or inside-out brush: check the face winding)")
        centre = tuple(sum(v[i] for v in self.verts) / len(self.verts) for i in range(3))
        for f, (n, d) in zip(faces, self.planes):
            on = [v for v in self.verts if dot(n, v) == d]
            if len(on) < 3:
                fail(f"{name}: face {f[1]} {f[2]} is redundant or degenerate ({len(on)} vertices)")
            if not dot(n, centre) < d:
                fail(f"{name}: face {f[1]} {f[2]} points into the brush")
            axis, sign = TAGS[f[2]]
            if n[axis] * sign <= 0 or any(abs(n[axis]) < abs(n[i]) for i in range(3)):
                fail(f"{name}: face tagged {f[2]} has normal {n}: wrong texture axes")
        self.lo = tuple(min(v[i] for v in self.verts) for i in range(3))
        self.hi = tuple(max(v[i] for v in self.verts) for i in range(3))

    def strictly_inside(self, p):
        return all(dot(n, p) < d for n, d in self.planes)

    def overlaps_box(self, lo, hi):
        """Positive-volume intersection with an axis-aligned box."""
        if any(self.hi[i] <= lo[i] or hi[i] <= self.lo[i] for i in range(3)):
            return False
        box_planes = [((1, 0, 0), hi[0]), ((-1, 0, 0), -lo[0]), ((0, 1, 0), hi[1]),
                      ((0, -1, 0), -lo[1]), ((0, 0, 1), hi[2]), ((0, 0, -1), -lo[2])]
        return has_volume(vertices(self.planes + box_planes))

    def overlaps(self, other):
        if any(self.hi[i] <= other.lo[i] or other.hi[i] <= self.lo[i] for i in range(3)):
            return False
        return has_volume(vertices(self.planes + other.planes))


def origin_of(e, units):
    try:
        x, y, z = (int(v) for v in e["origin"].split())
    except (KeyError, ValueError):
        fail(f'{e["classname"]}: missing or non-integer "origin"')
    return (x, y, z)


def on_floor(brushes, x, y, z):
    """A solid brush's top at height z under (x, y)."""
    return any(b.solid and b.hi[2] == z and b.lo[0] < x < b.hi[0] and b.lo[1] < y < b.hi[1]
               for b in brushes)


def check_sealed(brushes, starts):
    """Flood fill over the grid of brush boundaries; returns the entity that leaks, or None."""
    coords = [sorted({c for b in brushes for c in (b.lo[i], b.hi[i])}) for i in range(3)]
    for i in range(3):
        coords[i] = [coords[i][0] - 1] + coords[i] + [coords[i][-1] + 1]
    dims = [len(c) - 1 for c in coords]
    solid = bytearray(dims[0] * dims[1] * dims[2])

    def index(i, j, k):
        return (i * dims[1] + j) * dims[2] + k

    for b in brushes:
        if not b.seals:
            continue
        r = [range(bisect_left(coords[a], b.lo[a]), bisect_left(coords[a], b.hi[a])) for a in range(3)]
        for i in r[0]:
            for j in r[1]:
                for k in r[2]:
                    c = tuple(Fraction(coords[a][n] + coords[a][n + 1], 2) for a, n in ((0, i), (1, j), (2, k)))
                    if b.strictly_inside(c):
                        solid[index(i, j, k)] = 1
    for name, p in starts:
        cell = tuple(bisect_left(coords[a], p[a] + Fraction(1, 2)) - 1 for a in range(3))
        seen, todo = {cell}, deque([cell])
        while todo:
            i, j, k = todo.popleft()
            if i in (0, dims[0] - 1) or j in (0, dims[1] - 1) or k in (0, dims[2] - 1):
                return name
            for di, dj, dk in ((1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)):
                n = (i + di, j + dj, k + dk)
                if n not in seen and not solid[index(*n)]:
                    seen.add(n)
                    todo.append(n)
    return None


def check_sign(brushes, entities, sign, units):
    x, y, z = (sign[k] * units for k in ("x", "y", "z"))
    ww, wh = SIGN_WALL[0] * units, SIGN_WALL[1] * units
    # The sign faces west (angle 180): the wall is at x, the apron spans [x - 8 m, x].
    for dy in range(-ww // 2, ww // 2 + 1, units // 2):
        for dz in range(-wh // 2, wh // 2 + 1, units // 2):
            p = (x + Fraction(1, 2), y + dy, z + dz)
            if not any(b.seals and b.lo[0] == x and b.strictly_inside(p) for b in brushes):
                fail(f"sign: no plain wall at {p} behind it (needs {SIGN_WALL[0]} x {SIGN_WALL[1]} m)")
    lo = (x - SIGN_APRON * units, y - ww // 2, 0)
    hi = (x, y + ww // 2, z + wh // 2)
    for b in brushes:
        if b.overlaps_box(lo, hi):
            fail(f"sign: {b.name} stands in the {SIGN_APRON} m in front of the sign")
    for e in entities:
        if e["classname"] not in ("info_sign", "light"):
            p = origin_of(e, units)
            if all(lo[i] <= p[i] <= hi[i] for i in range(3)):
                fail(f'sign: {e["classname"]} at {p} stands in front of the sign')


def check_level(world, others, entities, units, sign, required_textures):
    """world / others: worldspawn and brush-entity brushes; sign: dict(x, y, z) in metres of an
    info_sign facing west, or None. Raises LevelError on the first problem; returns a summary."""
    brushes = [Brush(b, f"world brush {i}") for i, b in enumerate(world)]
    brushes += [Brush(b, f"entity brush {i}") for i, b in enumerate(others)]
    if len(brushes) >= MAX_BRUSHES:
        fail(f"{len(brushes)} brushes: keep it under {MAX_BRUSHES}")
    missing = required_textures - set().union(*(b.textures for b in brushes))
    if missing:
        fail(f"textures never used: {sorted(missing)}")
    for a, b in combinations(brushes, 2):
        if a.overlaps(b):
            fail(f"{a.name} and {b.name} overlap")
    starts, lights = [], 0
    for e in entities:
        cls, p = e["classname"], origin_of(e, units)
        name = f"{cls} at {p}"
        if any(b.solid and b.strictly_inside(p) for b in brushes):
            fail(f"{name} is inside a solid brush")
        starts.append((name, p))
        if cls.startswith("info_player"):
            feet = p[2] - PLAYER_ORIGIN_ABOVE_FEET
            lo = (p[0] - PLAYER_HALF_WIDTH, p[1] - PLAYER_HALF_WIDTH, feet)
            hi = (p[0] + PLAYER_HALF_WIDTH, p[1] + PLAYER_HALF_WIDTH, feet + PLAYER_HEIGHT)
            if not on_floor(brushes, p[0], p[1], feet):
                fail(f"{name}: feet ({PLAYER_ORIGIN_ABOVE_FEET} units below the origin) not on a floor")
            if any(b.solid and b.overlaps_box(lo, hi) for b in brushes):
                fail(f"{name}: the player's body intersects a brush")
        elif cls == "prop_crate":
            half = round(float(e["size"]) * units / 2)
            lo, hi = (p[0] - half, p[1] - half, p[2]), (p[0] + half, p[1] + half, p[2] + 2 * half)
            if not on_floor(brushes, p[0], p[1], p[2]) or any(b.solid and b.overlaps_box(lo, hi) for b in brushes):
                fail(f"{name}: not resting free on a floor")
        elif cls == "light":
            lights += 1
            if not 200 <= float(e["light"]) <= 400:
                fail(f"{name}: light {e['light']} outside 200-400")
            if not all(0 <= float(c) <= 1 for c in e["_color"].split()):
                fail(f"{name}: _color components must be 0..1")
    leak = check_sealed(brushes, starts)
    if leak:
        fail(f"leak: the space around {leak} reaches the outside (a gap, or it stands outside the sky box)")
    if sign:
        check_sign(brushes, entities, sign, units)
    faces = sum(len(b.faces) for b in brushes)
    return f"check passed: {faces} faces, {lights} lights, sealed, no overlaps"
