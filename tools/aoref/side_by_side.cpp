// obscura_side_by_side [--columns N] OUT.png IN.png...: the inputs (same size) in a grid, left to
// right then top to bottom (one row unless --columns), with 4-pixel dark gaps. For the AO modes'
// comparison images in the READMEs.
#include "core/image.h"

#include <iostream>
#include <string>

int main(int argc, char** argv) {
    int first = 1, columns = 0;
    if (argc > 2 && std::string(argv[1]) == "--columns") {
        columns = std::atoi(argv[2]);
        first = 3;
    }
    if (argc - first < 2 || (first == 3 && columns < 1)) {
        std::cerr << "usage: obscura_side_by_side [--columns N] OUT.png IN.png...\n";
        return 2;
    }
    try {
        constexpr int kGap = 4;
        std::vector<obscura::Image> in;
        for (int i = first + 1; i < argc; ++i) {
            in.push_back(obscura::readPng(argv[i]));
            if (in.back().width != in.front().width || in.back().height != in.front().height)
                throw std::runtime_error(std::string(argv[i]) + ": size differs from " + argv[first + 1]);
        }
        const int n = static_cast<int>(in.size());
        if (columns == 0) columns = n;
        const int rows = (n + columns - 1) / columns, w = in.front().width, h = in.front().height;
        const int width = columns * w + (columns - 1) * kGap, height = rows * h + (rows - 1) * kGap;
        obscura::Image out{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4, 32)};
        for (int i = 0; i < n; ++i) {
            const int x0 = (i % columns) * (w + kGap), y0 = (i / columns) * (h + kGap);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w * 4; ++x)
                    out.rgba[static_cast<std::size_t>((y0 + y) * width * 4 + x0 * 4 + x)] =
                        in[static_cast<std::size_t>(i)].rgba[static_cast<std::size_t>(y * w * 4 + x)];
        }
        for (std::size_t i = 3; i < out.rgba.size(); i += 4) out.rgba[i] = 255;
        obscura::writePng(out, argv[first]);
    } catch (const std::exception& e) {
        std::cerr << "obscura_side_by_side: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
