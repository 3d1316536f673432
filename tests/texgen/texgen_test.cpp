#include <gtest/gtest.h>

#include "texgen/texgen.h"

#include <cmath>
#include <cstdlib>

using namespace obscura;

namespace {
// Mean absolute difference between two columns (or rows) of an RGBA image.
double lineDifference(const Image& im, int a, int b, bool columns) {
    double sum = 0;
    for (int i = 0; i < im.width; ++i)
        for (int c = 0; c < 3; ++c) {
            const int pa = columns ? (i * im.width + a) : (a * im.width + i);
            const int pb = columns ? (i * im.width + b) : (b * im.width + i);
            sum += std::abs(int(im.rgba[static_cast<std::size_t>(pa * 4 + c)]) - int(im.rgba[static_cast<std::size_t>(pb * 4 + c)]));
        }
    return sum / (im.width * 3);
}
}  // namespace

TEST(Texgen, DeterministicPerNameAndDifferentAcrossNames) {
    EXPECT_EQ(texgen::generateTexture("brick", 64).rgba, texgen::generateTexture("BRICK", 64).rgba);  // case-insensitive
    EXPECT_NE(texgen::generateTexture("brick", 64).rgba, texgen::generateTexture("stone", 64).rgba);
    EXPECT_NE(texgen::generateTexture("grk_floor1", 64).rgba, texgen::generateTexture("grk_floor2", 64).rgba);  // fallbacks too
}

TEST(Texgen, TilesSeamlessly) {
    for (const char* name : {"concrete", "stone", "grass", "plaster", "unknown_name_42"}) {
        const Image im = texgen::generateTexture(name, 128);
        // Across the wrap (last -> first) no larger than between typical neighbours.
        double typical = 0;
        for (int i = 0; i + 1 < 128; ++i) typical += lineDifference(im, i, i + 1, true) / 127;
        EXPECT_LE(lineDifference(im, 127, 0, true), 2.5 * typical + 1.0) << name;
        EXPECT_LE(lineDifference(im, 127, 0, false), 2.5 * typical + 1.0) << name;
    }
}

TEST(Texgen, AlbedoStaysInARealisticRange) {
    for (const char* name : {"brick", "concrete", "tile_floor", "metal_floor", "wood_trim", "crate", "anything"}) {
        const Image im = texgen::generateTexture(name, 64);
        double mean = 0;
        for (std::size_t i = 0; i < im.rgba.size(); i += 4) {
            mean += (im.rgba[i] + im.rgba[i + 1] + im.rgba[i + 2]) / (3.0 * 255.0);
            EXPECT_EQ(im.rgba[i + 3], 255);
        }
        mean /= im.rgba.size() / 4.0;
        EXPECT_GT(mean, 0.15) << name;  // no black
        EXPECT_LT(mean, 0.85) << name;  // no white
    }
}
