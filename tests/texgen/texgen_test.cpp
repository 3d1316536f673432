// Texture generator: determinism, styles by keyword, the hash-coloured fallback, seamless tiling,
// albedo range, bad sizes; PNG round trip read back with libpng itself; the obscura_texgen tool.
#include <gtest/gtest.h>

#include "texgen/texgen.h"

#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <regex>
#include <string>

using namespace obscura;
namespace fs = std::filesystem;

namespace {

// Every style's keyword, with the liquids and an unknown name.
const char* const kStyles[] = {"brick", "concrete", "plaster", "tile_floor", "metal_floor", "wood_trim", "crate",
                               "stone", "grass", "sky", "*water", "*lava", "*teleport", "clip", "light1", "unknown_name_42"};

struct Mean {
    double r = 0, g = 0, b = 0;
    double luma() const { return (r + g + b) / 3; }
};

Mean meanColour(const Image& im) {
    Mean m;
    for (std::size_t i = 0; i < im.rgba.size(); i += 4) {
        m.r += im.rgba[i] / 255.0;
        m.g += im.rgba[i + 1] / 255.0;
        m.b += im.rgba[i + 2] / 255.0;
    }
    const double n = static_cast<double>(im.rgba.size() / 4);
    return {m.r / n, m.g / n, m.b / n};
}

// Mean absolute RGB difference between two columns (or rows) of a square image.
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

// Mean brightness of one row.
double rowLuma(const Image& im, int y) {
    double sum = 0;
    for (int x = 0; x < im.width; ++x)
        for (int c = 0; c < 3; ++c) sum += im.rgba[static_cast<std::size_t>((y * im.width + x) * 4 + c)];
    return sum / (im.width * 3 * 255.0);
}

// A scratch folder per test process, removed at the end.
struct TempDir {
    fs::path path;
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path = fs::temp_directory_path() / ("obscura_texgen_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

// Reads a PNG with libpng's simplified API (independent of obscura::readPng) as RGBA8.
Image readWithLibpng(const std::string& path) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    Image im;
    if (!png_image_begin_read_from_file(&png, path.c_str())) return im;
    png.format = PNG_FORMAT_RGBA;
    im.width = static_cast<int>(png.width);
    im.height = static_cast<int>(png.height);
    im.rgba.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, im.rgba.data(), 0, nullptr)) im = Image{};
    return im;
}

}  // namespace

TEST(Texgen, SameNameSameBytes) {
    for (const char* name : kStyles) {
        const Image a = texgen::generateTexture(name, 64), b = texgen::generateTexture(name, 64);
        EXPECT_EQ(a.rgba, b.rgba) << name;
        EXPECT_EQ(a.width, 64);
        EXPECT_EQ(a.height, 64);
        EXPECT_EQ(a.rgba.size(), 64u * 64u * 4u);
    }
    EXPECT_EQ(texgen::generateTexture("brick", 64).rgba, texgen::generateTexture("BRICK", 64).rgba);  // case-insensitive
    EXPECT_EQ(texgen::nameHash("Stone"), texgen::nameHash("stone"));
    EXPECT_EQ(texgen::nameHash("a"), 0xe40c292cu);  // FNV-1a 32-bit of "a" (published test vector)
}

TEST(Texgen, DifferentNamesDiffer) {
    for (std::size_t i = 0; i < std::size(kStyles); ++i)
        for (std::size_t j = i + 1; j < std::size(kStyles); ++j)
            EXPECT_NE(texgen::generateTexture(kStyles[i], 32).rgba, texgen::generateTexture(kStyles[j], 32).rgba)
                << kStyles[i] << " vs " << kStyles[j];
    // Same style, different names: still different textures.
    EXPECT_NE(texgen::generateTexture("brick1", 64).rgba, texgen::generateTexture("brick2", 64).rgba);
    EXPECT_NE(texgen::generateTexture("grk_floor1", 64).rgba, texgen::generateTexture("grk_floor2", 64).rgba);
}

TEST(Texgen, KeywordsPickTheStyle) {
    const Mean brick = meanColour(texgen::generateTexture("old_brick_wall", 64));
    EXPECT_GT(brick.r, brick.g + 0.1) << "brick is red";
    const Mean grass = meanColour(texgen::generateTexture("grass_field", 64));
    EXPECT_GT(grass.g, grass.r);
    EXPECT_GT(grass.g, grass.b + 0.1) << "grass is green";
    const Mean water = meanColour(texgen::generateTexture("*water1", 64));
    EXPECT_GT(water.b, water.r + 0.1) << "water is blue";
    const Mean lava = meanColour(texgen::generateTexture("*lava1", 64));
    EXPECT_GT(lava.r, lava.b + 0.3) << "lava is orange";
    // A teleporter is violet with sparkles, not a pool of water (it was drawn as *water1's blue).
    const Mean tele = meanColour(texgen::generateTexture("*teleport", 64));
    EXPECT_GT(tele.r, tele.g + 0.05) << "teleporter is violet";
    EXPECT_GT(tele.b, tele.r) << "teleporter is violet";
    EXPECT_GT(tele.r - tele.g, water.r - water.g + 0.1) << "not water";
    const Mean sky = meanColour(texgen::generateTexture("sky", 64));
    EXPECT_GT(sky.b, sky.r + 0.1) << "sky is blue";
    const Mean wood = meanColour(texgen::generateTexture("crate_big", 64));
    EXPECT_GT(wood.r, wood.b + 0.15) << "wood is brown";
    // Neutral greys: concrete, metal, stone, tile.
    for (const char* grey : {"concrete", "metal_floor", "stone", "tile_floor"}) {
        const Mean m = meanColour(texgen::generateTexture(grey, 64));
        EXPECT_LT(std::max({m.r, m.g, m.b}) - std::min({m.r, m.g, m.b}), 0.08) << grey;
    }
    // A light panel's diffuser is the brightest surface.
    EXPECT_GT(meanColour(texgen::generateTexture("light1", 64)).luma(), meanColour(texgen::generateTexture("concrete", 64)).luma());
    // The keyword wins over the hash: two tile names share the grout grid at quarter-tile lines.
    for (const char* tile : {"tile_floor", "bathroom_tile"}) {
        const Image im = texgen::generateTexture(tile, 128);
        EXPECT_LT(rowLuma(im, 32), rowLuma(im, 48) - 0.1) << tile;
    }
}

TEST(Texgen, FallbackIsAMutedColourWithAFaintGrid) {
    for (int i = 0; i < 40; ++i) {
        const std::string name = "no_such_texture_" + std::to_string(i);
        const Image im = texgen::generateTexture(name, 128);
        const Mean m = meanColour(im);
        const double mx = std::max({m.r, m.g, m.b}), mn = std::min({m.r, m.g, m.b});
        EXPECT_GE(mx, 0.35) << name << ": not dark";
        EXPECT_LE(mx, 0.8) << name << ": not glaring";
        EXPECT_GE((mx - mn) / mx, 0.15) << name << ": coloured";
        EXPECT_LE((mx - mn) / mx, 0.6) << name << ": not garish";
        // Grid lines every quarter tile, darker than the cells between them, but only faintly.
        const double line = (rowLuma(im, 32) + rowLuma(im, 64) + rowLuma(im, 96)) / 3;
        const double cell = (rowLuma(im, 16) + rowLuma(im, 48) + rowLuma(im, 80)) / 3;
        EXPECT_LT(line, cell * 0.92) << name << ": grid visible";
        EXPECT_GT(line, cell * 0.7) << name << ": grid faint";
    }
}

TEST(Texgen, TilesSeamlessly) {
    for (const char* name : kStyles) {
        const Image im = texgen::generateTexture(name, 128);
        // Across the wrap (last -> first column / row) no larger than between typical neighbours.
        double typicalColumns = 0, typicalRows = 0;
        for (int i = 0; i + 1 < 128; ++i) {
            typicalColumns += lineDifference(im, i, i + 1, true) / 127;
            typicalRows += lineDifference(im, i, i + 1, false) / 127;
        }
        EXPECT_LE(lineDifference(im, 127, 0, true), 2.5 * typicalColumns + 1.0) << name;
        EXPECT_LE(lineDifference(im, 127, 0, false), 2.5 * typicalRows + 1.0) << name;
    }
}

TEST(Texgen, SeamCheckCatchesANonTilingImage) {
    // The criterion above must be able to fail: a horizontal ramp does not tile.
    Image ramp;
    ramp.width = ramp.height = 128;
    ramp.rgba.resize(128 * 128 * 4);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x)
            for (int c = 0; c < 4; ++c) ramp.rgba[static_cast<std::size_t>((y * 128 + x) * 4 + c)] = static_cast<std::uint8_t>(60 + x);
    double typical = 0;
    for (int i = 0; i + 1 < 128; ++i) typical += lineDifference(ramp, i, i + 1, true) / 127;
    EXPECT_GT(lineDifference(ramp, 127, 0, true), 2.5 * typical + 1.0);
}

TEST(Texgen, AlbedoStaysInARealisticRange) {
    for (const char* name : kStyles) {
        const Image im = texgen::generateTexture(name, 64);
        int lo = 255, hi = 0;
        for (std::size_t i = 0; i < im.rgba.size(); i += 4) {
            lo = std::min({lo, int(im.rgba[i]), int(im.rgba[i + 1]), int(im.rgba[i + 2])});
            hi = std::max({hi, int(im.rgba[i]), int(im.rgba[i + 1]), int(im.rgba[i + 2])});
            ASSERT_EQ(im.rgba[i + 3], 255) << name;
        }
        EXPECT_GE(lo, 5) << name << ": no pure black";
        EXPECT_LE(hi, 250) << name << ": no pure white";
        const double luma = meanColour(im).luma();
        EXPECT_GT(luma, 0.2) << name;
        EXPECT_LT(luma, 0.8) << name;
    }
}

TEST(Texgen, BadSizeThrows) {
    EXPECT_THROW(texgen::generateTexture("brick", 0), texgen::TexgenError);
    EXPECT_THROW(texgen::generateTexture("brick", -128), texgen::TexgenError);
    EXPECT_THROW(texgen::generateTexture("brick", 1 << 20), texgen::TexgenError);
    try {
        texgen::generateTexture("brick", 4);
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("'brick'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("size 4"), std::string::npos) << e.what();
    }
    EXPECT_EQ(texgen::generateTexture("brick", texgen::kMinSize).width, texgen::kMinSize);
}

TEST(Texgen, PngRoundTripThroughLibpng) {
    TempDir dir;
    const Image im = texgen::generateTexture("metal_floor", 128);
    const std::string path = (dir.path / "metal_floor.png").string();
    writePng(im, path);
    const Image back = readWithLibpng(path);
    EXPECT_EQ(back.width, 128);
    EXPECT_EQ(back.height, 128);
    EXPECT_EQ(back.rgba, im.rgba);
}

TEST(Texgen, PngWriteFailureNamesTheFile) {
    const std::string path = "/nonexistent_dir_obscura/x.png";
    try {
        writePng(texgen::generateTexture("brick", 8), path);
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
}

TEST(TexgenTool, WritesOnePngPerNameWithItsFolders) {
    TempDir dir;
    const std::string cmd = std::string(OBSCURA_TEXGEN_TOOL) + " " + (dir.path / "out").string() + " brick e1u1/metal_floor";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    EXPECT_EQ(readWithLibpng((dir.path / "out/brick.png").string()).rgba, texgen::generateTexture("brick", 128).rgba);
    EXPECT_EQ(readWithLibpng((dir.path / "out/e1u1/metal_floor.png").string()).rgba,
              texgen::generateTexture("e1u1/metal_floor", 128).rgba);
    const std::string quiet = " 2>/dev/null";
    EXPECT_NE(std::system((std::string(OBSCURA_TEXGEN_TOOL) + " " + (dir.path / "out").string() + " ../escape" + quiet).c_str()), 0);
    EXPECT_FALSE(fs::exists(dir.path / "escape.png"));
}

// TrenchBroom's texture browser shows the build's generated/textures: every texture a shipped map
// names (media/levels, tests/*/levels) is there, tool and liquid textures included.
TEST(TexgenTool, TheEditorSetHoldsEveryTextureTheShippedMapsUse) {
    std::set<std::string> used;
    const std::regex face(R"(^\( [^)]*\) \( [^)]*\) \( [^)]*\) (\S+))");
    std::vector<fs::path> maps;
    for (const auto& e : fs::directory_iterator(fs::path(OBSCURA_SOURCE_DIR) / "media/levels"))
        if (e.path().extension() == ".map") maps.push_back(e.path());
    for (const auto& suite : fs::directory_iterator(fs::path(OBSCURA_SOURCE_DIR) / "tests"))
        if (fs::is_directory(suite.path() / "levels"))
            for (const auto& e : fs::directory_iterator(suite.path() / "levels"))
                if (e.path().extension() == ".map") maps.push_back(e.path());
    for (const fs::path& m : maps) {
        std::ifstream in(m);
        std::string line;
        std::smatch hit;
        while (std::getline(in, line))
            if (std::regex_search(line, hit, face)) used.insert(hit[1]);
    }
    ASSERT_GE(maps.size(), 10u);
    for (const char* t : {"brick", "trigger", "clip", "hint", "*water1", "sky"}) EXPECT_TRUE(used.count(t)) << t;  // the scan reads faces
    for (const std::string& t : used)
        EXPECT_TRUE(fs::is_regular_file(fs::path(OBSCURA_GENERATED_DIR) / "textures" / (t + ".png"))) << t << " is not in the editor's set";
}

TEST(TexgenTool, FailsCleanlyOnBadArguments) {
    TempDir dir;
    const std::string tool = OBSCURA_TEXGEN_TOOL;
    const std::string quiet = " 2>/dev/null";
    EXPECT_NE(std::system((tool + quiet).c_str()), 0) << "no arguments";
    EXPECT_NE(std::system((tool + " " + dir.path.string() + " ''" + quiet).c_str()), 0) << "empty name";
    const fs::path file = dir.path / "a_file";
    { std::FILE* f = std::fopen(file.string().c_str(), "w"); ASSERT_NE(f, nullptr); std::fclose(f); }
    EXPECT_NE(std::system((tool + " " + file.string() + " brick" + quiet).c_str()), 0) << "output dir is a file";
}

TEST(Texgen, FenceNamesGetAGrilleWithHoles) {
    // `{` textures (map/surface_rules.h) are alpha-tested: alpha 0 in the holes, 255 on the bars,
    // bars 3/8 of a cell wide: 1 - 0.625^2 = 61 % opaque.
    for (const char* name : {"{grate", "{FENCE1", "wad/{chain"}) {
        const Image img = texgen::generateTexture(name, 128);
        int opaque = 0, clear = 0;
        for (std::size_t i = 3; i < img.rgba.size(); i += 4) {
            opaque += img.rgba[i] == 255;
            clear += img.rgba[i] == 0;
        }
        EXPECT_EQ(opaque + clear, 128 * 128) << name;  // a mask, nothing in between
        EXPECT_NEAR(opaque / (128.0 * 128.0), 0.61, 0.01) << name;
        // A hole in the middle of the first cell (16 x 16 texels), a bar along its edge.
        EXPECT_EQ(img.rgba[(8 * 128 + 8) * 4 + 3], 0) << name;
        EXPECT_EQ(img.rgba[(8 * 128 + 0) * 4 + 3], 255) << name;
    }
    const Image solid = texgen::generateTexture("grate", 64);
    for (std::size_t i = 3; i < solid.rgba.size(); i += 4) ASSERT_EQ(solid.rgba[i], 255);
}
