// obscura_fgd OUT_FILE : writes the entity-class registry (engine_ext/map/entity_classes.cpp) as
// the FGD TrenchBroom reads. `cmake --build build --target update_fgd` runs it into
// tools/trenchbroom/obscura/obscura.fgd; tests/map/fgd_test.cpp checks the committed file is current.
// Exit status 2 for bad usage, 1 (with the reason on stderr) when the file cannot be written.
#include "map/entity_classes.h"
#include "map/fgd.h"

#include <exception>
#include <fstream>
#include <iostream>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: obscura_fgd OUT_FILE\n";
        return 2;
    }
    try {
        const std::string text = obscura::map::writeFgd(obscura::map::keyGroups(), obscura::map::entityClasses());
        std::ofstream out(argv[1], std::ios::binary);
        out << text;
        out.close();
        if (!out) {
            std::cerr << "obscura_fgd: cannot write " << argv[1] << "\n";
            return 1;
        }
    } catch (const std::exception& e) {
        std::cerr << "obscura_fgd: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
