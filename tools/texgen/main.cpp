// obscura_texgen OUT_DIR NAME... : writes OUT_DIR/<NAME>.png for each texture name (slashes become
// underscores), 128 x 128. Run by the build for the textures media/materials/level.material names.
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
            std::string file = argv[i];
            if (file.empty()) throw std::runtime_error("argument " + std::to_string(i) + ": empty texture name");
            for (char& c : file)
                if (c == '/') c = '_';
            obscura::writePng(obscura::texgen::generateTexture(argv[i], 128),
                              (std::filesystem::path(argv[1]) / (file + ".png")).string());
        }
    } catch (const std::exception& e) {
        std::cerr << "obscura_texgen: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
