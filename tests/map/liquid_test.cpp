// Liquids (map/liquid.h): classification by name and by Quake 2 content bits, skip faces, the
// alpha keys, faces buried against walls, and point-in-liquid queries.
#include <gtest/gtest.h>

#include "map/liquid.h"
#include "map/map_compile.h"
#include "test_maps.h"

using namespace obscura;
using namespace obscura::map;
using testdata::cube;
using testdata::entity;

namespace {
using testdata::compile;
const std::string kWorld = "\"classname\" \"worldspawn\"\n\"mapversion\" \"220\"";

std::size_t visibleFaces(const LevelBrush& b) {
    std::size_t n = 0;
    for (const auto& f : b.faces) n += f.visible;
    return n;
}

// A cube whose top face (index 3 in testdata::cube) has texture `top`.
std::string cubeWithTop(int x, int y, int z, const std::string& tex, const std::string& top, int size = 64) {
    std::string c = cube(x, y, z, tex, size);
    std::size_t at = 0;
    for (int line = 0; line < 4; ++line) at = c.find('\n', at) + 1;  // "{" and faces 0..2
    const std::size_t texAt = c.find(") " + tex + " [", at) + 2;
    return c.replace(texAt, tex.size(), top);
}
}  // namespace

TEST(Liquid, KindsByNameAsQuake) {
    EXPECT_EQ(liquidKindOfTexture("*water1"), LiquidKind::Water);
    EXPECT_EQ(liquidKindOfTexture("*04water"), LiquidKind::Water);
    EXPECT_EQ(liquidKindOfTexture("*blood1"), LiquidKind::Water);  // anything else with '*'
    EXPECT_EQ(liquidKindOfTexture("*SLIME0"), LiquidKind::Slime);
    EXPECT_EQ(liquidKindOfTexture("*lava1"), LiquidKind::Lava);
    EXPECT_EQ(liquidKindOfTexture("*teleport"), LiquidKind::Teleport);
    EXPECT_EQ(liquidKindOfTexture("water"), LiquidKind::None);
    EXPECT_EQ(liquidKindOfTexture(""), LiquidKind::None);
    EXPECT_EQ(liquidKindOfContents(32), LiquidKind::Water);
    EXPECT_EQ(liquidKindOfContents(16 | 32), LiquidKind::Slime);
    EXPECT_EQ(liquidKindOfContents(8 | 1), LiquidKind::Lava);
    EXPECT_EQ(liquidKindOfContents(1), LiquidKind::None);
    EXPECT_TRUE(isLiquidSkipTexture("*WaterSkip"));
    EXPECT_TRUE(isLiquidSkipTexture("*lavaskip"));
    EXPECT_TRUE(isLiquidSkipTexture("*skip"));
    EXPECT_FALSE(isLiquidSkipTexture("*water1"));
    EXPECT_FALSE(isLiquidSkipTexture("skip"));  // the ordinary skip is isInvisibleTexture's
}

TEST(Liquid, BrushIsANonSolidVolumeAndSkipFacesAreHidden) {
    const Level l = compile(entity(kWorld, cubeWithTop(0, 0, 0, "*waterskip", "*water1")));
    ASSERT_EQ(l.brushes.size(), 1u);
    const LevelBrush& b = l.brushes[0];
    EXPECT_EQ(b.liquid, LiquidKind::Water);
    EXPECT_FALSE(b.solid);
    EXPECT_EQ(b.faces.size(), 6u);  // every plane kept: the volume stays closed
    EXPECT_EQ(visibleFaces(b), 1u);  // only the surface
    EXPECT_TRUE(b.visible);
    for (const auto& f : b.faces) EXPECT_EQ(f.visible, f.texture == "*water1");
    EXPECT_EQ(b.liquidAlpha, 1.0);  // no key: opaque, as Quake
}

TEST(Liquid, MostHarmfulFaceDecidesTheKind) {
    const Level l = compile(entity(kWorld, cubeWithTop(0, 0, 0, "*water1", "*lava1")));
    EXPECT_EQ(l.brushes[0].liquid, LiquidKind::Lava);
}

TEST(Liquid, AlphaKeysFollowQuakeSpasm) {
    const std::string slime = cube(0, 0, 0, "*slime0"), water = cube(128, 0, 0, "*water1"), tele = cube(256, 0, 0, "*teleport");
    {
        // _wateralpha with its underscore; slime has its own key; the teleporter falls back to water's.
        const Level l = compile(entity(kWorld + "\n\"_wateralpha\" \"0.5\"\n\"slimealpha\" \"0.75\"", slime + water + tele));
        EXPECT_DOUBLE_EQ(l.brushes[0].liquidAlpha, 0.75);
        EXPECT_DOUBLE_EQ(l.brushes[1].liquidAlpha, 0.5);
        EXPECT_DOUBLE_EQ(l.brushes[2].liquidAlpha, 0.5);
    }
    {
        // A func_water's own alpha wins over worldspawn's.
        const Level l = compile(entity(kWorld + "\n\"wateralpha\" \"0.5\"") +
                                entity("\"classname\" \"func_water\"\n\"_alpha\" \"0.25\"", water));
        ASSERT_EQ(l.brushes.size(), 1u);
        EXPECT_DOUBLE_EQ(l.brushes[0].liquidAlpha, 0.25);
        EXPECT_FALSE(l.brushes[0].solid);
        // ... and so does its own _wateralpha.
        const Level k = compile(entity(kWorld + "\n\"wateralpha\" \"0.5\"") +
                                entity("\"classname\" \"func_water\"\n\"_wateralpha\" \"0.3\"", water));
        EXPECT_DOUBLE_EQ(k.brushes[0].liquidAlpha, 0.3);
    }
    {
        // Out of range or not a number: a warning naming the line, and the key is ignored.
        std::vector<std::string> w;
        const Level l = compile(entity(kWorld + "\n\"_wateralpha\" \"1.5\"", water), &w);
        EXPECT_DOUBLE_EQ(l.brushes[0].liquidAlpha, 1.0);
        bool named = false;
        for (const auto& s : w) named |= s.find("t.map:1:") == 0 && s.find("_wateralpha") != std::string::npos;
        EXPECT_TRUE(named);
    }
}

TEST(Liquid, Quake2ContentBitsMakeWaterNonSolidAndTranslucent) {
    // A Quake 2 face: "... rot xscale yscale contents surfaceflags value". CONTENTS_WATER 32 on a
    // texture without '*', SURF_TRANS33 on the top.
    std::string c = cube(0, 0, 0, "e1u1/water1_8");
    std::string out;
    std::size_t line = 0, from = 0;
    for (std::size_t nl; (nl = c.find('\n', from)) != std::string::npos; from = nl + 1, ++line) {
        std::string l = c.substr(from, nl - from);
        if (l.rfind("(", 0) == 0) l += line == 4 ? " 32 16 0" : " 32 0 0";
        out += l + "\n";
    }
    const Level l = compile(entity(kWorld, out));
    ASSERT_EQ(l.brushes.size(), 1u);
    EXPECT_EQ(l.brushes[0].liquid, LiquidKind::Water);
    EXPECT_FALSE(l.brushes[0].solid);
    EXPECT_DOUBLE_EQ(l.brushes[0].liquidAlpha, 0.33);
    const MapFile m = parseMap(entity(kWorld, out), "t.map");
    EXPECT_TRUE(m.entities[0].brushes[0].faces[0].hasFlags);
    EXPECT_EQ(m.entities[0].brushes[0].faces[0].contents, 32);
    EXPECT_FALSE(parseMap(entity(kWorld, cube(0, 0, 0)), "t.map").entities[0].brushes[0].faces[0].hasFlags);
}

TEST(Liquid, FacesAgainstWallsAreHidden) {
    // A 64-unit water cube sunk in a pit: stone on all four sides and below; the top is open.
    std::string walls = cube(-64, 0, 0, "stone") + cube(64, 0, 0, "stone") + cube(0, -64, 0, "stone") + cube(0, 64, 0, "stone") +
                        cube(0, 0, -64, "stone");
    const Level l = compile(entity(kWorld, walls + cube(0, 0, 0, "*water1")));
    const LevelBrush& water = l.brushes.back();
    ASSERT_EQ(water.liquid, LiquidKind::Water);
    ASSERT_EQ(visibleFaces(water), 1u);
    for (const auto& f : water.faces)
        if (f.visible) {
            EXPECT_GT(f.normal.y, 0.99);  // the surface, facing up
        }
}

TEST(Liquid, PointQueries) {
    const Level l = compile(entity(kWorld, cube(0, 0, 0, "*water1") + cube(32, 0, 0, "*lava1", 16)));
    const LiquidQuery q(l);
    EXPECT_EQ(q.size(), 2u);
    // Quake (x, y, z) -> (x, z, -y) / 32.
    const auto at = [&](double x, double y, double z) { return q.at(Vec3{x, z, -y} / 32.0); };
    EXPECT_EQ(at(16, 16, 16), LiquidKind::Water);
    EXPECT_EQ(at(40, 8, 8), LiquidKind::Lava);  // inside both: lava wins
    EXPECT_EQ(at(16, 16, 65), LiquidKind::None);
    EXPECT_EQ(at(-1, 16, 16), LiquidKind::None);
    EXPECT_EQ(at(16, 16, 64), LiquidKind::Water);  // the surface itself counts
    EXPECT_TRUE(pointInBrush(l.brushes[0], Vec3{16, 16, -16} / 32.0));
    EXPECT_FALSE(pointInBrush(l.brushes[0], Vec3{16, 70, -16} / 32.0));
    EXPECT_TRUE(LiquidQuery(compile(entity(kWorld, cube(0, 0, 0)))).empty());
}
