#!/usr/bin/python3
"""Tests for make_arena.py and its self-check (levelcheck.py): the committed arena.map is the
script's current output, the arena passes, and each kind of mistake is caught.
Run: /usr/bin/python3 tools/levelgen/test_levelcheck.py (CTest runs it as Levelgen.SelfCheck)."""
import contextlib
import io
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # no __pycache__ beside the sources
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_arena as arena  # noqa: E402  (builds the arena's brush lists; writes nothing)
from levelcheck import LevelError, check_level  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
U = arena.UNITS


def shell(x0, y0, z0, x1, y1, z1, t=0.5):
    """Six sky slabs enclosing the box (x0, y0, z0)-(x1, y1, z1)."""
    return [arena.box(x0, y0, z0 - t, x1, y1, z0, "sky"), arena.box(x0, y0, z1, x1, y1, z1 + t, "sky"),
            arena.box(x0 - t, y0, z0 - t, x0, y1, z1 + t, "sky"), arena.box(x1, y0, z0 - t, x1 + t, y1, z1 + t, "sky"),
            arena.box(x0, y0 - t, z0 - t, x1, y0, z1 + t, "sky"), arena.box(x0, y1, z0 - t, x1, y1 + t, z1 + t, "sky")]


def small_level():
    """A 4 x 4 m floor in a sky box with a player start in the middle."""
    world = [arena.box(0, 0, -0.5, 4, 4, 0, "concrete")] + shell(0, 0, -0.5, 4, 4, 3)
    ents = [{"classname": "info_player_start", "origin": arena.point(2, 2, 0.75), "angle": "0"}]
    return world, ents


def check(world, ents, others=(), sign=None):
    return check_level(world, list(others), ents, U, sign=sign, required_textures=set())


class ArenaTest(unittest.TestCase):
    def test_committed_map_is_the_scripts_output(self):
        out = io.StringIO()
        arena.write(out)
        with open(os.path.join(ROOT, "media/levels/arena.map")) as f:
            self.assertEqual(f.read(), out.getvalue(), "re-run make_arena.py media/levels/arena.map")

    def test_arena_passes(self):
        summary = check_level(arena.brushes, [arena.TRIGGER], arena.entities, U, sign=arena.SIGN,
                              required_textures={"brick", "sky", "clip"})
        self.assertIn("sealed", summary)

    def test_every_face_line_has_the_valve220_shape(self):
        for b in arena.brushes:
            for f in b:
                parts = arena.face_line(f).split()
                self.assertEqual(len(parts), 31, parts)  # 3 x 5 point tokens, texture, 2 x 6 axis tokens, 3 numbers
                self.assertEqual([parts[i] for i in (0, 4, 5, 9, 10, 14, 16, 21, 22, 27)],
                                 ["(", ")", "(", ")", "(", ")", "[", "]", "[", "]"])

    def test_sign_apron_must_stay_empty(self):
        pillar = arena.box(40, 31, 0, 40.5, 31.5, 3, "stone")  # 4 m in front of the sign
        with self.assertRaisesRegex(LevelError, "in front of the sign"):
            check_level(arena.brushes + [pillar], [arena.TRIGGER], arena.entities, U, sign=arena.SIGN,
                        required_textures=set())

    def test_a_failing_check_writes_nothing(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "arena.map")
            arena.brushes.append(arena.box(40, 31, 0, 40.5, 31.5, 3, "stone"))  # in front of the sign
            try:
                with contextlib.redirect_stderr(io.StringIO()) as err:
                    self.assertEqual(arena.main([out]), 1)
            finally:
                arena.brushes.pop()
            self.assertFalse(os.path.exists(out))
            self.assertIn("check failed, nothing written", err.getvalue())
            with contextlib.redirect_stderr(io.StringIO()):
                self.assertEqual(arena.main([out]), 0)
            self.assertTrue(os.path.getsize(out) > 0)

    def test_sign_needs_a_wall_behind_it(self):
        sign = dict(arena.SIGN, x=40)  # in the middle of the courtyard
        with self.assertRaisesRegex(LevelError, "no plain wall"):
            check_level(arena.brushes, [arena.TRIGGER], arena.entities, U, sign=sign, required_textures=set())


class CheckerCatchesMistakes(unittest.TestCase):
    def test_small_level_passes(self):
        world, ents = small_level()
        self.assertIn("check passed", check(world, ents))

    def test_inward_face(self):
        world, ents = small_level()
        pts, tex, tag = world[0][3]
        world[0][3] = ((pts[0], pts[2], pts[1]), tex, tag)  # the top face's points reversed
        with self.assertRaisesRegex(LevelError, "world brush 0: (no volume|face concrete \\+z points into)"):
            check(world, ents)

    def test_wrong_texture_axes_tag(self):
        world, ents = small_level()
        pts, tex, _ = world[0][3]
        world[0][3] = (pts, tex, "+x")
        with self.assertRaisesRegex(LevelError, "wrong texture axes"):
            check(world, ents)

    def test_box_with_an_extra_slope_plane_is_not_a_wedge(self):
        world, ents = small_level()
        bad = arena.box(1, 1, 0, 3, 2, 1, "concrete")
        bad.append(arena.face((1, 1, 0), (1, 2, 0), (3, 1, 1), "concrete", "+z"))  # 7 planes
        with self.assertRaisesRegex(LevelError, "7 faces"):
            check(world + [bad], ents)

    def test_degenerate_face(self):
        world, ents = small_level()
        wedge = arena.ramp_x(1, 3, 1, 1.5, 0, 0, 1, "concrete")
        wedge.append(arena.box(1, 1, 0, 3, 1.5, 1, "concrete")[0])  # a -x face of zero area
        with self.assertRaisesRegex(LevelError, "redundant or degenerate"):
            check(world + [wedge], ents)

    def test_overlap(self):
        world, ents = small_level()
        world += [arena.box(0.5, 0.5, 0, 1.5, 1.5, 1, "stone"), arena.box(1, 1, 0.5, 2, 2, 1.5, "stone")]
        with self.assertRaisesRegex(LevelError, "overlap"):
            check(world, ents)

    def test_touching_is_fine(self):
        world, ents = small_level()
        world += [arena.box(0.5, 0.5, 0, 1.5, 1.5, 1, "stone"), arena.box(1.5, 0.5, 0, 2, 1.5, 1, "stone")]
        check(world, ents)

    def test_leak(self):
        world, ents = small_level()
        del world[3]  # a side slab of the sky box
        with self.assertRaisesRegex(LevelError, "leak: the space around info_player_start"):
            check(world, ents)

    def test_clip_does_not_seal(self):
        world, ents = small_level()
        pts = world[3]
        world[3] = [(p, "clip", tag) for p, _, tag in pts]
        with self.assertRaisesRegex(LevelError, "leak"):
            check(world, ents)

    def test_entity_in_a_wall(self):
        world, ents = small_level()
        world.append(arena.box(0.5, 0.5, 0, 1.5, 1.5, 2, "stone"))
        ents.append({"classname": "light", "origin": arena.point(1, 1, 1), "light": "300", "_color": "1 1 1"})
        with self.assertRaisesRegex(LevelError, "inside a solid brush"):
            check(world, ents)

    def test_floating_player_start(self):
        world, ents = small_level()
        ents[0]["origin"] = arena.point(2, 2, 2)
        with self.assertRaisesRegex(LevelError, "not on a floor"):
            check(world, ents)

    def test_player_start_too_close_to_a_wall(self):
        world, ents = small_level()
        world.append(arena.box(2.25, 1, 0, 3, 3, 2, "stone"))  # 0.25 m from the origin: body is 0.5 m wide
        with self.assertRaisesRegex(LevelError, "body intersects"):
            check(world, ents)

    def test_light_out_of_range(self):
        world, ents = small_level()
        ents.append({"classname": "light", "origin": arena.point(2, 2, 2), "light": "900", "_color": "1 1 1"})
        with self.assertRaisesRegex(LevelError, "outside 200-400"):
            check(world, ents)

    def test_steep_ramp_and_high_step_refused_by_the_helpers(self):
        with self.assertRaisesRegex(AssertionError, "steeper"):
            arena.ramp_x(0, 1, 0, 1, 0, 0, 1, "concrete")  # 45 degrees
        with self.assertRaisesRegex(AssertionError, "steps up"):
            arena.stairs_y(0, 1, 0, 0, 2, 19 / 32, 0.5, "concrete")  # 19 units: one past the step


if __name__ == "__main__":
    unittest.main()
