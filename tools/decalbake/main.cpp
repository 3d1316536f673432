// obscura_decalbake: the decal atlas, baked by the build (tools/decalbake/CMakeLists.txt).
//   obscura_decalbake ATLAS.png FONT.ttf                 the atlas (shaders/decals/decals_shared.h)
//   obscura_decalbake --mask MASK.png --size N OUT.png   one signed distance field from a PNG mask
// Errors name the file and end the run with status 1.
#include "decals/atlas.h"
#include "decals/decals_shared.h"

#include <cstring>
#include <iostream>
#include <string>

using namespace obscura;

int main(int argc, char** argv) {
    try {
        if (argc == 6 && std::strcmp(argv[1], "--mask") == 0 && std::strcmp(argv[3], "--size") == 0) {
            const int size = std::atoi(argv[4]);
            if (size < 1 || size > 1024) throw decals::BakeError(std::string("--size ") + argv[4] + ": expected 1..1024");
            Image out;
            out.width = out.height = size;
            out.rgba.assign(static_cast<std::size_t>(size) * size * 4, 0);
            decals::bakeMaskTile(out, 0, size, decals::maskFromPng(argv[2]));
            writePng(out, argv[5]);
            return 0;
        }
        if (argc != 3) {
            std::cerr << "usage: obscura_decalbake ATLAS.png FONT.ttf | --mask MASK.png --size N OUT.png\n";
            return 2;
        }
        writePng(decals::bakeAtlas(argv[2]), argv[1]);
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "obscura_decalbake: " << e.what() << "\n";
        return 1;
    }
}
