#!/usr/bin/env python3
"""CTest TrenchBroom.GameConfig: the committed GameConfig.cfg passes check_gameconfig.py, and the
check fails on doctored copies (so it can fail). Stdlib only."""
import os
import shutil
import sys
import tempfile

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_gameconfig  # noqa: E402

FOLDER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "obscura")


def doctored(old, new):
    tmp = tempfile.mkdtemp()
    shutil.copy(os.path.join(FOLDER, "obscura.fgd"), tmp)
    text = open(os.path.join(FOLDER, "GameConfig.cfg"), encoding="utf-8").read()
    assert old in text, old
    open(os.path.join(tmp, "GameConfig.cfg"), "w", encoding="utf-8").write(text.replace(old, new, 1))
    return check_gameconfig.problems(tmp)


def main():
    failures = []
    real = check_gameconfig.problems(FOLDER)
    if real:
        failures.append(f"committed config: {real}")
    cases = [('"version": 9', '"version": 8', "version 8"),
             ('"obscura.fgd"', '"other.fgd"', "'other.fgd' not beside it"),
             ('"root": "textures"', '"root": "tex"', "expected .png in generated/textures"),
             ('"format": "Valve" },', '"format": "Quake3" },', "expected Valve then Standard"),
             ('"name": "Obscura"', '"name": "Obscura", }', "Expecting")]  # not JSON any more
    for old, new, expected in cases:
        got = doctored(old, new)
        if not any(expected in p for p in got):
            failures.append(f"{old} -> {new}: expected a problem with {expected!r}, got {got}")
    for f in failures:
        print("FAIL:", f)
    print("ok" if not failures else f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
