#include <gtest/gtest.h>

#include "map/map_compile.h"
#include "test_maps.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>

using namespace obscura;
using namespace obscura::map;
using testdata::cube;
using testdata::entity;

namespace {
Level compile(const std::string& text, std::vector<std::string>* warnings = nullptr) {
    return compileLevel(parseMap(text, "t.map"), {}, warnings);
}

// Every polygon planar, convex, counter-clockwise around its normal.
void expectWellFormed(const LevelPolygon& p) {
    ASSERT_GE(p.vertices.size(), 3u);
    const auto& v0 = p.vertices[0].position;
    for (std::size_t i = 0; i < p.vertices.size(); ++i) {
        const Vec3& a = p.vertices[i].position;
        const Vec3& b = p.vertices[(i + 1) % p.vertices.size()].position;
        const Vec3& c = p.vertices[(i + 2) % p.vertices.size()].position;
        EXPECT_NEAR(dot(a - v0, p.normal), 0.0, 1e-6);
        EXPECT_GE(dot(cross(b - a, c - b), p.normal), -1e-9);
    }
}
}  // namespace

TEST(MapCompile, ConvertsToMetresYUpKeepingWindingOutward) {
    const Level l = compile(entity("\"classname\" \"worldspawn\"", cube(0, 0, 0)));
    ASSERT_EQ(l.brushes.size(), 1u);
    const LevelBrush& b = l.brushes[0];
    EXPECT_EQ(b.faces.size(), 6u);
    EXPECT_EQ(b.hullPoints.size(), 8u);
    // Quake (0..64, 0..64, 0..64) at 32 units/m -> x 0..2, y (up) 0..2, z -2..0.
    EXPECT_NEAR(b.bounds.min.x, 0, 1e-9);
    EXPECT_NEAR(b.bounds.max.y, 2, 1e-9);
    EXPECT_NEAR(b.bounds.min.z, -2, 1e-9);
    EXPECT_NEAR(b.bounds.max.z, 0, 1e-9);
    const Vec3 centre{1, 1, -1};
    bool sawUp = false;
    for (const auto& p : b.faces) {
        expectWellFormed(p);
        Vec3 c;
        for (const auto& v : p.vertices) c += v.position;
        c = c / static_cast<double>(p.vertices.size());
        EXPECT_GT(dot(p.normal, c - centre), 0.0);
        sawUp |= p.normal.y > 0.99;  // Quake +Z is now +Y
    }
    EXPECT_TRUE(sawUp);
}

TEST(MapCompile, UvsAreTexelsOverTextureSize) {
    CompileOptions o;
    o.textureSize = [](const std::string&) { return std::make_pair(128, 32); };
    const Level l = compileLevel(parseMap(entity("\"classname\" \"worldspawn\"", cube(0, 0, 0)), "t.map"), o);
    for (const auto& p : l.brushes[0].faces)
        for (const auto& v : p.vertices) {
            // uAxis = +x (Quake) = +x (world), vAxis = -y (Quake) = +z (world); scale 1, offset 0.
            EXPECT_NEAR(v.u, v.position.x * 32 / 128, 1e-9);
            EXPECT_NEAR(v.v, v.position.z * 32 / 32, 1e-9);
        }
}

TEST(MapCompile, ScaleFromWorldspawnOrOptions) {
    const std::string text = entity("\"classname\" \"worldspawn\"\n\"units_per_metre\" \"64\"", cube(0, 0, 0));
    EXPECT_NEAR(compile(text).brushes[0].bounds.max.x, 1.0, 1e-9);
    CompileOptions o;
    o.unitsPerMetre = 16;
    EXPECT_NEAR(compileLevel(parseMap(text, "t.map"), o).brushes[0].bounds.max.x, 4.0, 1e-9);
}

TEST(MapCompile, EntityClassesDecideVisibilityAndSolidity) {
    const std::string text = entity("\"classname\" \"worldspawn\"", cube(0, 0, 0) + cube(100, 0, 0, "clip") + cube(200, 0, 0, "*water1")) +
                             entity("\"classname\" \"trigger_once\"", cube(300, 0, 0)) +
                             entity("\"classname\" \"func_illusionary\"", cube(400, 0, 0)) +
                             entity("\"classname\" \"func_detail_wall\"", cube(500, 0, 0)) +
                             entity("\"classname\" \"monster_ogre\"\n\"origin\" \"0 0 0\"") +
                             entity("\"classname\" \"monster_ogre\"\n\"origin\" \"8 0 0\"") +
                             entity("\"classname\" \"weapon_nailgun\"\n\"origin\" \"8 0 0\"");
    const Level l = compile(text);
    ASSERT_EQ(l.brushes.size(), 6u);
    EXPECT_TRUE(l.brushes[0].visible && l.brushes[0].solid);
    EXPECT_TRUE(!l.brushes[1].visible && l.brushes[1].solid);   // clip: invisible, blocks
    EXPECT_TRUE(l.brushes[2].visible && !l.brushes[2].solid);   // liquid
    EXPECT_TRUE(!l.brushes[3].visible && !l.brushes[3].solid);  // trigger
    EXPECT_TRUE(l.brushes[4].visible && !l.brushes[4].solid);   // illusionary
    EXPECT_TRUE(l.brushes[5].visible && l.brushes[5].solid);    // detail
    ASSERT_EQ(l.unknownClassnames.size(), 2u);  // each listed once
    EXPECT_EQ(l.unknownClassnames[0], "monster_ogre");
    EXPECT_EQ(l.unknownClassnames[1], "weapon_nailgun");
}

TEST(MapCompile, PlayerStartLightsAndModels) {
    const std::string text = entity("\"classname\" \"worldspawn\"", cube(0, 0, -64)) +
                             entity("\"classname\" \"info_player_deathmatch\"\n\"origin\" \"500 0 24\"") +
                             entity("\"classname\" \"info_player_start\"\n\"origin\" \"32 64 24\"\n\"angle\" \"90\"") +
                             entity("\"classname\" \"light\"\n\"origin\" \"0 0 96\"\n\"light\" \"320\"\n\"_color\" \"255 128 0\"") +
                             entity("\"classname\" \"misc_model\"\n\"origin\" \"64 0 0\"\n\"model\" \"cornell.mesh\"\n\"scale\" \"2\"");
    std::vector<std::string> warnings;
    const Level l = compile(text, &warnings);
    ASSERT_TRUE(l.hasPlayerStart);
    EXPECT_NEAR(l.playerStart.x, 1, 1e-9);
    EXPECT_NEAR(l.playerStart.y, 0, 1e-9);  // feet: 24 units below the origin
    EXPECT_NEAR(l.playerStart.z, -2, 1e-9);
    // Quake angle 90 faces +Y (Quake) = -Z (world): OGRE's yaw 0.
    EXPECT_NEAR(l.playerStartYaw, 0.0, 1e-12);
    ASSERT_EQ(l.lights.size(), 1u);
    EXPECT_NEAR(l.lights[0].position.y, 3, 1e-9);
    EXPECT_NEAR(l.lights[0].radius, 10, 1e-9);
    EXPECT_NEAR(l.lights[0].colour.y, 128.0 / 255.0, 1e-9);
    ASSERT_EQ(l.models.size(), 1u);
    EXPECT_EQ(l.models[0].mesh, "cornell.mesh");
    EXPECT_DOUBLE_EQ(l.models[0].scale, 2);
    EXPECT_TRUE(warnings.empty());
}

TEST(MapCompile, BadBrushIsSkippedWithItsLine) {
    std::vector<std::string> warnings;
    const Level l = compile(entity("\"classname\" \"worldspawn\"",
                                   cube(0, 0, 0) + "{\n( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) t 0 0 0 1 1\n}\n"),
                            &warnings);
    EXPECT_EQ(l.brushes.size(), 1u);
    ASSERT_FALSE(warnings.empty());
    EXPECT_NE(warnings[0].find("t.map:11: brush skipped"), std::string::npos) << warnings[0];
}

TEST(MapCompile, LibreQuakeE3m4LoadsWhole) {
    const std::filesystem::path path = std::filesystem::path(OBSCURA_SHARED_DIR) / "maps/librequake/e3m4.map";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
    const auto t0 = std::chrono::steady_clock::now();
    const MapFile m = loadMapFile(path.string());
    const auto t1 = std::chrono::steady_clock::now();
    std::vector<std::string> warnings;
    const Level l = compileLevel(m, {}, &warnings);
    const auto t2 = std::chrono::steady_clock::now();

    std::size_t brushes = 0, faces = 0, visible = 0;
    for (const auto& e : m.entities) brushes += e.brushes.size();
    for (const auto& b : l.brushes)
        for (const auto& p : b.faces) {
            ++faces;
            visible += p.visible;
            expectWellFormed(p);
        }
    std::cout << "e3m4: parse " << std::chrono::duration<double, std::milli>(t1 - t0).count() << " ms, compile "
              << std::chrono::duration<double, std::milli>(t2 - t1).count() << " ms; " << brushes << " brushes parsed, "
              << l.brushes.size() << " compiled, " << warnings.size() << " warnings; " << faces << " faces ("
              << visible << " visible); " << l.lights.size() << " lights; " << l.unknownClassnames.size()
              << " unknown classes\n";
    // The file holds 4,742 `{` blocks: 1,301 entities and 3,441 brushes (its `// brush N` comments).
    EXPECT_EQ(m.entities.size(), 1301u);
    EXPECT_EQ(brushes, 3441u);
    EXPECT_EQ(l.brushes.size() + warnings.size(), brushes);  // every brush compiled or reported
    EXPECT_TRUE(l.hasPlayerStart);
    EXPECT_GT(l.lights.size(), 100u);
    // About 8,000 x 8,000 Quake units at most: metres, sane.
    EXPECT_GT(l.bounds.max.x - l.bounds.min.x, 20.0);
    EXPECT_LT(l.bounds.max.x - l.bounds.min.x, 300.0);
}
