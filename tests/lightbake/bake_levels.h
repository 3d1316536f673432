// Small levels for the light bake's tests, as .map text (Quake units, z up; 32 units a metre).
#pragma once

#include "lightbake/light_bake.h"
#include "map/map_compile.h"
#include "map/map_parser.h"

#include <cmath>
#include <string>

namespace obscura::lightbake::testdata {

// An axis-aligned box brush from (x0, y0, z0) to (x1, y1, z1), Quake units.
inline std::string box(int x0, int y0, int z0, int x1, int y1, int z1, const std::string& tex = "wall") {
    auto p = [](int x, int y, int z) { return "( " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + " ) "; };
    const std::string t = tex + " 0 0 0 1 1\n";
    return "{\n" + p(x0, 0, 0) + p(x0, 1, 0) + p(x0, 0, 1) + t +  // -x
           p(x1, 0, 0) + p(x1, 0, 1) + p(x1, 1, 0) + t +           // +x
           p(0, y0, 0) + p(0, y0, 1) + p(1, y0, 0) + t +           // -y
           p(0, y1, 0) + p(1, y1, 0) + p(0, y1, 1) + t +           // +y
           p(0, 0, z0) + p(1, 0, z0) + p(0, 1, z0) + t +           // -z
           p(0, 0, z1) + p(0, 1, z1) + p(1, 0, z1) + t + "}\n";    // +z
}

// The walls, floor and (unless `open`) roof of a room with interior [x0, x1] x [y0, y1] x [0, h],
// walls `t` units thick.
inline std::string room(int x0, int y0, int x1, int y1, int h, int t, bool open = false) {
    std::string s = box(x0 - t, y0 - t, -t, x1 + t, y1 + t, 0) +  // floor
                    box(x0 - t, y0 - t, 0, x0, y1 + t, h) + box(x1, y0 - t, 0, x1 + t, y1 + t, h) +
                    box(x0, y0 - t, 0, x1, y0, h) + box(x0, y1, 0, x1, y1 + t, h);
    if (!open) s += box(x0 - t, y0 - t, h, x1 + t, y1 + t, h + t);
    return s;
}

inline map::Level compile(const std::string& text) { return map::compileLevel(map::parseMap(text, "t.map")); }

// A Quake point (units, z up) in the level's metres (Y up).
inline Vec3 metres(double x, double y, double z) { return Vec3{x, z, -y} / 32.0; }

}  // namespace obscura::lightbake::testdata
