// obscura_side_by_side OUT.png IN.png...: the inputs (same height) side by side, left to right,
// with a 4-pixel dark gap. For the AO modes' comparison images in the READMEs.
#include "core/image.h"

#include <iostream>

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: obscura_side_by_side OUT.png IN.png...\n";
        return 2;
    }
    try {
        constexpr int kGap = 4;
        std::vector<obscura::Image> in;
        int width = 0, height = 0;
        for (int i = 2; i < argc; ++i) {
            in.push_back(obscura::readPng(argv[i]));
            if (i > 2 && in.back().height != height) throw std::runtime_error(std::string(argv[i]) + ": height differs");
            height = in.back().height;
            width += in.back().width + (i > 2 ? kGap : 0);
        }
        obscura::Image out{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4, 32)};
        int x0 = 0;
        for (const auto& im : in) {
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < im.width * 4; ++x)
                    out.rgba[static_cast<std::size_t>(y * width * 4 + x0 * 4 + x)] = im.rgba[static_cast<std::size_t>(y * im.width * 4 + x)];
            x0 += im.width + kGap;
        }
        for (std::size_t i = 3; i < out.rgba.size(); i += 4) out.rgba[i] = 255;
        obscura::writePng(out, argv[1]);
    } catch (const std::exception& e) {
        std::cerr << "obscura_side_by_side: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
