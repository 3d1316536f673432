// Small .map texts shared by the map tests.
#pragma once

#include "map/map_compile.h"
#include "map/map_parser.h"

#include <string>
#include <vector>

namespace obscura::map::testdata {

// A 64-unit cube from (x0,y0,z0), exactly as TrenchBroom writes one (Valve-220).
inline std::string cube(int x0, int y0, int z0, const std::string& tex = "tex", int size = 64) {
    const std::string a = std::to_string(x0), b = std::to_string(y0), c = std::to_string(z0);
    const std::string A = std::to_string(x0 + size), B = std::to_string(y0 + size), C = std::to_string(z0 + size);
    const std::string A1 = std::to_string(x0 + size + 1), B1 = std::to_string(y0 + size + 1), C1 = std::to_string(z0 + size + 1);
    const std::string a1 = std::to_string(x0 + 1), b1 = std::to_string(y0 + 1), c1 = std::to_string(z0 + 1);
    const std::string uv = " [ 1 0 0 0 ] [ 0 -1 0 0 ] 0 1 1\n";
    return "{\n"
           "( " + a + " " + b + " " + c + " ) ( " + a + " " + b1 + " " + c + " ) ( " + a + " " + b + " " + c1 + " ) " + tex + uv +
           "( " + a + " " + b + " " + c + " ) ( " + a + " " + b + " " + c1 + " ) ( " + a1 + " " + b + " " + c + " ) " + tex + uv +
           "( " + a + " " + b + " " + c + " ) ( " + a1 + " " + b + " " + c + " ) ( " + a + " " + b1 + " " + c + " ) " + tex + uv +
           "( " + A + " " + B + " " + C + " ) ( " + A + " " + B1 + " " + C + " ) ( " + A1 + " " + B + " " + C + " ) " + tex + uv +
           "( " + A + " " + B + " " + C + " ) ( " + A1 + " " + B + " " + C + " ) ( " + A + " " + B + " " + C1 + " ) " + tex + uv +
           "( " + A + " " + B + " " + C + " ) ( " + A + " " + B + " " + C1 + " ) ( " + A + " " + B1 + " " + C + " ) " + tex + uv +
           "}\n";
}

inline std::string entity(const std::string& keys, const std::string& brushes = "") {
    return "{\n" + keys + "\n" + brushes + "}\n";
}

// A .map text compiled as the game compiles a level file ("t.map" in messages).
inline Level compile(const std::string& text, std::vector<std::string>* warnings = nullptr) {
    return compileLevel(parseMap(text, "t.map"), {}, warnings);
}

}  // namespace obscura::map::testdata
