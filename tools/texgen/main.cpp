// obscura_texgen OUT_DIR NAME... : writes OUT_DIR/<NAME>.png for each texture name, 128 x 128 (a
// name's folders become folders: e1u1/sky1 -> OUT_DIR/e1u1/sky1.png, as TrenchBroom looks for it).
// Run by the build for the textures media/materials/level.material names and the editor's set.
// Exit status 2 for bad usage, 1 (with the reason on stderr) for an empty name or a failed write.
#include "texgen/texgen.h"

#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: obscura_texgen OUT_DIR NAME...\n";
        return 2;
    }
    try {
        std::filesystem::create_directories(argv[1]);
        for (int i = 2; i < argc; ++i) {
            const std::string name = argv[i];
            if (name.empty()) throw std::runtime_error("argument " + std::to_string(i) + ": empty texture name");
            if (name.front() == '/' || name.find("..") != std::string::npos)
                throw std::runtime_error("argument " + std::to_string(i) + ": '" + name + "' leaves the output folder");
            const std::filesystem::path file = std::filesystem::path(argv[1]) / (name + ".png");
            std::filesystem::create_directories(file.parent_path());
            obscura::writePng(obscura::texgen::generateTexture(name, 128), file.string());
        }
    } catch (const std::exception& e) {
        std::cerr << "obscura_texgen: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
