#!/usr/bin/env python3
"""Checks tools/trenchbroom/obscura/GameConfig.cfg: JSON once its // comments are gone (TrenchBroom
allows them), version 9, the fields TrenchBroom requires, the FGD it names beside it, and a
search path + material root that is where tools/texgen writes the textures in the build folder.
Exit status 1 with one line per problem. Usage: check_gameconfig.py GAME_FOLDER"""
import json
import os
import sys


def strip_comments(text):
    out, i, in_string = [], 0, False
    while i < len(text):
        c = text[i]
        if in_string:
            out.append(c)
            if c == "\\":
                out.append(text[i + 1])
                i += 1
            elif c == '"':
                in_string = False
        elif c == '"':
            in_string = True
            out.append(c)
        elif text.startswith("//", i):
            while i < len(text) and text[i] != "\n":
                i += 1
            continue
        else:
            out.append(c)
        i += 1
    return "".join(out)


def problems(folder):
    path = os.path.join(folder, "GameConfig.cfg")
    try:
        cfg = json.loads(strip_comments(open(path, encoding="utf-8").read()))
    except (OSError, ValueError) as e:
        return [f"{path}: {e}"]
    found = []
    if cfg.get("version") != 9:
        found.append(f"{path}: version {cfg.get('version')!r}, expected 9")
    if cfg.get("name") != "Obscura":
        found.append(f"{path}: name {cfg.get('name')!r}, expected 'Obscura'")
    formats = [f.get("format") for f in cfg.get("fileformats", [])]
    if formats[:2] != ["Valve", "Standard"]:
        found.append(f"{path}: fileformats {formats}, expected Valve then Standard")
    fs = cfg.get("filesystem", {})
    if "searchpath" not in fs or "packageformat" not in fs:
        found.append(f"{path}: filesystem needs searchpath and packageformat")
    materials = cfg.get("materials", {})
    where = os.path.join(fs.get("searchpath", "?"), materials.get("root", "?"))
    if where != "generated/textures" or ".png" not in materials.get("extensions", []):
        found.append(f"{path}: materials at {where!r} ({materials.get('extensions')}), expected .png in generated/textures")
    entities = cfg.get("entities", {})
    for d in entities.get("definitions", []) or ["(none)"]:
        if not os.path.isfile(os.path.join(folder, d)):
            found.append(f"{path}: entity definitions {d!r} not beside it")
    if "defaultcolor" not in entities:
        found.append(f"{path}: entities need a defaultcolor")
    return found


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    p = problems(sys.argv[1])
    for line in p:
        print(line)
    sys.exit(1 if p else 0)
