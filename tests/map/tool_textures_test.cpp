// Tool textures by Quake's, Quake 2's, Quake 3's and Source's rules (map/surface_rules.h's
// toolSurface), folder-qualified names included, and what they do to a brush in the compiler:
// hint, origin and monster-clip brushes vanish; clip and all-skip brushes stay solid and unseen.
#include <gtest/gtest.h>

#include "map/map_compile.h"
#include "map/surface_rules.h"
#include "test_maps.h"

using namespace obscura::map;
using testdata::cube;
using testdata::entity;

TEST(ToolTextures, NamesAreMatchedOnTheBaseNameCaseInsensitively) {
    const std::pair<const char*, ToolSurface> cases[] = {
        {"hint", ToolSurface::Hint},          {"e1u1/hint", ToolSurface::Hint},       {"HINTSKIP", ToolSurface::Hint},
        {"tools/toolshint", ToolSurface::Hint}, {"skip", ToolSurface::Skip},          {"common/skip", ToolSurface::Skip},
        {"clip", ToolSurface::Clip},          {"e1u1/CLIP", ToolSurface::Clip},       {"common/playerclip", ToolSurface::Clip},
        {"tools/toolsclip", ToolSurface::Clip}, {"clip_mon", ToolSurface::MonsterClip}, {"e1u1/clip_mon", ToolSurface::MonsterClip},
        {"common/monsterclip", ToolSurface::MonsterClip}, {"tools/toolsnpcclip", ToolSurface::MonsterClip},
        {"trigger", ToolSurface::Trigger},    {"e1u1/trigger", ToolSurface::Trigger}, {"origin", ToolSurface::Origin},
        {"common/origin", ToolSurface::Origin}, {"nodraw", ToolSurface::NoDraw},      {"common/caulk", ToolSurface::NoDraw},
        {"common/weapclip_unknown", ToolSurface::NoDraw}, {"tools/toolsblack", ToolSurface::NoDraw},
        {"triggered_wall", ToolSurface::None}, {"skipper", ToolSurface::None},        {"eclipse", ToolSurface::None},
        {"toolshint", ToolSurface::None},     {"e1u1/hint_wall", ToolSurface::None},  {"*water1", ToolSurface::None}};
    for (const auto& [name, expected] : cases) EXPECT_EQ(toolSurface(name), expected) << name;
}

TEST(ToolTextures, QuakeTwoBitsWinOverTheName) {
    EXPECT_EQ(toolSurface("e1u1/wall", true, 0, kQ2SurfHint), ToolSurface::Hint);
    EXPECT_EQ(toolSurface("e1u1/wall", true, 0, kQ2SurfSkip), ToolSurface::Skip);
    EXPECT_EQ(toolSurface("e1u1/wall", true, kQ2ContentsPlayerClip | kQ2ContentsMonsterClip, 0), ToolSurface::Clip);
    EXPECT_EQ(toolSurface("e1u1/wall", true, kQ2ContentsMonsterClip, 0), ToolSurface::MonsterClip);
    EXPECT_EQ(toolSurface("e1u1/wall", true, kQ2ContentsOrigin, 0), ToolSurface::Origin);
    EXPECT_EQ(toolSurface("e1u1/wall", true, 1, kQ2SurfNoDraw), ToolSurface::NoDraw);
    EXPECT_EQ(toolSurface("e1u1/wall", true, 1, 0), ToolSurface::None);
    EXPECT_EQ(toolSurface("e1u1/clip", true, 0, 0), ToolSurface::Clip);  // an editor that writes 0 0 0 keeps the name's rule
}

TEST(ToolTextures, HintOriginAndMonsterClipBrushesVanishClipAndSkipStaySolidAndUnseen) {
    const std::string text = entity("\"classname\" \"worldspawn\"",
                                    cube(0, 0, 0) + cube(128, 0, 0, "e1u1/hint") + cube(256, 0, 0, "clip_mon") +
                                        cube(384, 0, 0, "origin") + cube(512, 0, 0, "common/clip") + cube(640, 0, 0, "skip") +
                                        cube(768, 0, 0, "nodraw"));
    const Level l = compileLevel(parseMap(text, "t.map"));
    ASSERT_EQ(l.brushes.size(), 4u);  // the plain cube, the clip, the skip, the nodraw
    EXPECT_TRUE(l.brushes[0].visible);
    for (std::size_t i = 1; i < 4; ++i) {
        EXPECT_TRUE(l.brushes[i].solid) << i;
        EXPECT_FALSE(l.brushes[i].visible) << i;
    }
    EXPECT_NEAR(l.brushes[1].bounds.min.x, 512.0 / 32, 1e-9);
}

TEST(ToolTextures, AHintBrushWithSkipSidesVanishesAndSkipFacesOnAWallAreNotDrawn) {
    // A hint brush: one hint face, the rest skip (how TrenchBroom users make one).
    std::string hint = cube(0, 0, 0, "skip");
    hint.replace(hint.find("skip"), 4, "hint");
    std::string wall = cube(128, 0, 0, "brick");
    wall.replace(wall.find("brick"), 5, "skip");
    const Level l = compileLevel(parseMap(entity("\"classname\" \"worldspawn\"", hint + wall), "t.map"));
    ASSERT_EQ(l.brushes.size(), 1u);
    EXPECT_TRUE(l.brushes[0].solid);
    int drawn = 0;
    for (const auto& f : l.brushes[0].faces) drawn += f.visible ? 1 : 0;
    EXPECT_EQ(drawn, 5);
}
