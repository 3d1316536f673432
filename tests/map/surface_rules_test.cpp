// Sky and fence faces by the Quake family's name rules and Quake 2's flags (map/surface_rules.h),
// through the parser (the trailing `contents flags value` triple) and the compiler.
#include <gtest/gtest.h>

#include "map/map_compile.h"
#include "map/map_parser.h"
#include "map/surface_rules.h"
#include "test_maps.h"

using namespace obscura::map;
using namespace obscura::map::testdata;

namespace {
Level compileText(const std::string& text) {
    return compileLevel(parseMap(text, "t.map"), {}, nullptr);
}

// One brush face line with a texture and an optional tail after the texture axes.
std::string oneFaceMap(const std::string& faceTail) {
    return "{\n\"classname\" \"worldspawn\"\n{\n( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) tex [ 1 0 0 0 ] [ 0 -1 0 0 ] 0 1 1" + faceTail +
           "\n( 0 0 64 ) ( 1 0 64 ) ( 0 1 64 ) tex 0 0 0 1 1\n}\n}\n";
}
}  // namespace

TEST(SurfaceRules, SkyIsQuakesPrefixRuleAnyCaseBelowAnyFolder) {
    for (const char* t : {"sky", "sky1", "SKY4", "Sky_Dev_Day", "sky_dev_day", "skyb", "e1u1/sky1", "wad/sky4", "WAD\\SKY1",
                          "textures/e1u1/sky2"})
        EXPECT_TRUE(isSkyTexture(t)) << t;
    for (const char* t : {"", "sk", "s", "blue_sky", "e1u1/floor_sky", "sky/floor", "*sky", "{sky", "ksy1"})
        EXPECT_FALSE(isSkyTexture(t)) << t;
    EXPECT_EQ(textureBaseName("e1u1/sky1"), "sky1");
    EXPECT_EQ(textureBaseName("a\\b/c"), "c");
    EXPECT_EQ(textureBaseName("plain"), "plain");
}

TEST(SurfaceRules, Quake2SurfSkyMakesAnyTextureSky) {
    EXPECT_TRUE(isSkyFace("e1u1/clouds", kQ2SurfSky));
    EXPECT_TRUE(isSkyFace("e1u1/clouds", kQ2SurfSky | kQ2SurfLight));
    EXPECT_FALSE(isSkyFace("e1u1/clouds", 0));
    EXPECT_FALSE(isSkyFace("e1u1/clouds", kQ2SurfLight | kQ2SurfWarp | kQ2SurfTrans33 | kQ2SurfNoDraw));
    EXPECT_TRUE(isSkyFace("sky1", 0));
}

TEST(SurfaceRules, FenceIsABraceFirstInTheBaseName) {
    for (const char* t : {"{grate", "{FENCE1", "wad/{chain", "e1u1/{bars"}) EXPECT_TRUE(isFenceTexture(t)) << t;
    for (const char* t : {"", "grate{", "grate", "*{water", "+0{button", "{/grate"}) EXPECT_FALSE(isFenceTexture(t)) << t;
}

TEST(MapParser, KeepsQuake2ContentsFlagsAndValue) {
    // Valve-220 and classic faces, each with and without the triple (TrenchBroom writes Quake 2
    // faces as `... rot xscale yscale contents flags value`).
    {
        const MapFile m = parseMap(oneFaceMap(" 1 4 300"), "t.map");
        const MapFace& f = m.entities.at(0).brushes.at(0).faces.at(0);
        EXPECT_TRUE(f.hasFlags);
        EXPECT_EQ(f.contents, 1u);
        EXPECT_EQ(f.surfaceFlags, kQ2SurfSky);
        EXPECT_EQ(f.value, 300);
        const MapFace& g = m.entities.at(0).brushes.at(0).faces.at(1);
        EXPECT_FALSE(g.hasFlags);
        EXPECT_EQ(g.surfaceFlags, 0u);
    }
    {
        // Large bit sets and a negative value (qbsp reads them with atoi: the 32-bit pattern).
        const MapFile m = parseMap(oneFaceMap(" 134217728 -1 0"), "t.map");
        const MapFace& f = m.entities.at(0).brushes.at(0).faces.at(0);
        EXPECT_EQ(f.contents, 134217728u);  // CONTENTS_DETAIL
        EXPECT_EQ(f.surfaceFlags, 0xFFFFFFFFu);
    }
    {
        const MapFile m = parseMap(oneFaceMap(" 0 0"), "t.map");  // a short tail: read, not kept
        EXPECT_FALSE(m.entities.at(0).brushes.at(0).faces.at(0).hasFlags);
    }
}

TEST(MapCompile, SkyAndFenceFacesByNameAndFlags) {
    std::string q2 = cube(128, 0, 0, "e1u1/clouds");
    // The Quake 2 cube's faces carry SURF_SKY in their triple.
    for (std::size_t at = q2.find(" 0 1 1\n"); at != std::string::npos; at = q2.find(" 0 1 1\n", at + 1))
        q2.replace(at, 7, " 0 1 1 0 4 0\n");
    const Level l = compileText(entity("\"classname\" \"worldspawn\"",
                                       cube(0, 0, 0, "e1u1/sky1") + cube(256, 0, 0, "SKY4") + q2 + cube(384, 0, 0, "{grate") +
                                           cube(512, 0, 0, "e1u1/clouds")));
    ASSERT_EQ(l.brushes.size(), 5u);
    const bool sky[] = {true, true, true, false, false};
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_TRUE(l.brushes[i].solid) << i;  // sky and fence brushes block like walls
        EXPECT_TRUE(l.brushes[i].visible) << i;
        for (const auto& p : l.brushes[i].faces) {
            EXPECT_EQ(p.sky, sky[i]) << p.texture;
            EXPECT_EQ(p.fence, i == 3) << p.texture;
            EXPECT_TRUE(p.visible) << p.texture;
        }
    }
    EXPECT_EQ(l.brushes[2].faces[0].surfaceFlags, kQ2SurfSky);
    EXPECT_EQ(l.brushes[4].faces[0].surfaceFlags, 0u);
}
