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
constexpr double kPi = 3.14159265358979323846;

using testdata::compile;

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

TEST(MapCompile, MoverBrushesAreSolidButApartFromTheWorld) {
    const std::string text = entity("\"classname\" \"worldspawn\"", cube(0, 0, 0)) +
                             entity("\"classname\" \"func_door\"", cube(100, 0, 0)) +
                             entity("\"classname\" \"func_plat\"", cube(200, 0, 0)) +
                             entity("\"classname\" \"func_wall\"", cube(300, 0, 0));
    const Level l = compile(text);
    ASSERT_EQ(l.brushes.size(), 4u);
    EXPECT_FALSE(l.brushes[0].mover);
    EXPECT_TRUE(l.brushes[1].mover && l.brushes[1].solid && l.brushes[1].visible);
    EXPECT_EQ(l.brushes[1].entityIndex, 1);
    EXPECT_TRUE(l.brushes[2].mover);
    EXPECT_FALSE(l.brushes[3].mover);  // func_wall stays static
    EXPECT_TRUE(isMoverClass("func_train") && isMoverClass("func_button") && isMoverClass("func_door_secret"));
    EXPECT_FALSE(isMoverClass("func_detail") || isMoverClass("trigger_once"));
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
    const std::filesystem::path path = std::filesystem::path(OBSCURA_THIRD_PARTY_DIR) / "librequake/e3m4.map";
    const auto t0 = std::chrono::steady_clock::now();
    const MapFile m = loadMapFile(path.string());
    const auto t1 = std::chrono::steady_clock::now();
    std::vector<std::string> warnings;
    const Level l = compileLevel(m, {}, &warnings);
    const auto t2 = std::chrono::steady_clock::now();

    std::size_t brushes = 0, faces = 0, visible = 0, skipped = 0;
    for (const auto& e : m.entities) brushes += e.brushes.size();
    for (const auto& w : warnings) skipped += w.find("brush skipped") != std::string::npos;
    for (const auto& b : l.brushes) {
        ASSERT_GE(b.hullPoints.size(), 4u);
        Vec3 inside;
        for (const auto& h : b.hullPoints) inside += h;
        inside = inside / static_cast<double>(b.hullPoints.size());
        for (const auto& p : b.faces) {
            ++faces;
            visible += p.visible;
            expectWellFormed(p);
            // Outward: the brush's interior lies behind every face.
            EXPECT_LT(dot(p.normal, inside - p.vertices[0].position), 0.0) << "brush at line " << b.pos.line;
        }
    }
    std::cout << "e3m4: parse " << std::chrono::duration<double, std::milli>(t1 - t0).count() << " ms, compile "
              << std::chrono::duration<double, std::milli>(t2 - t1).count() << " ms; " << m.entities.size()
              << " entities, " << brushes << " brushes parsed, " << l.brushes.size() << " compiled, " << skipped
              << " rejected, " << warnings.size() << " warnings; " << faces << " faces (" << visible << " visible); "
              << l.lights.size() << " lights; " << l.unknownClassnames.size() << " unknown classes\n";
    // The file holds 4,742 `{` blocks: 1,301 entities and 3,441 brushes (its `// brush N` comments).
    EXPECT_EQ(m.entities.size(), 1301u);
    EXPECT_EQ(brushes, 3441u);
    EXPECT_EQ(m.entities.size() + brushes, 4742u);
    // Every brush compiled, reported, or left out with its entity: at skill 1, 20 entities
    // (monsters, armour, a func_wall's 1 brush) carry NOT_MEDIUM; e3m4 has no hint or origin brush.
    std::size_t leftOutBrushes = 0;
    for (std::size_t i = 1; i < m.entities.size(); ++i)
        if (leftOutAtSkill(std::atoi(m.entities[i].value("spawnflags").c_str()), kDefaultSkill)) leftOutBrushes += m.entities[i].brushes.size();
    EXPECT_EQ(l.leftOutEntities, 20);
    EXPECT_EQ(l.entities.size(), m.entities.size() - 20);
    EXPECT_EQ(leftOutBrushes, 1u);
    EXPECT_EQ(l.brushes.size() + skipped + leftOutBrushes, brushes);
    EXPECT_LT(skipped, brushes / 100);               // a real, editor-checked map: almost all compile
    EXPECT_TRUE(l.hasPlayerStart);
    EXPECT_GT(l.lights.size(), 100u);
    // The player starts inside the level's bounds.
    for (int k = 0; k < 3; ++k) {
        EXPECT_GT(l.playerStart[k], l.bounds.min[k]);
        EXPECT_LT(l.playerStart[k], l.bounds.max[k]);
    }
    // A few thousand Quake units across: tens of metres, sane.
    for (int k = 0; k < 3; ++k) {
        EXPECT_GT(l.bounds.max[k] - l.bounds.min[k], 10.0);
        EXPECT_LT(l.bounds.max[k] - l.bounds.min[k], 300.0);
    }
}

TEST(MapCompile, TextureClassesAreCaseInsensitive) {
    for (const char* t : {"clip", "CLIP", "playerclip", "common/clip", "trigger", "Trigger", "skip", "hint", "HINTSKIP",
                          "nodraw", "caulk", "common/caulk", "Common/NoDraw"})
        EXPECT_TRUE(isInvisibleTexture(t)) << t;
    for (const char* t : {"sky1", "*water1", "*lava1", "base_floor", "triggered_wall", "skipper", "+0button"})
        EXPECT_FALSE(isInvisibleTexture(t)) << t;
    for (const char* t : {"*water1", "*lava1", "*slime0", "*teleport", "*04water"}) EXPECT_TRUE(isLiquidTexture(t)) << t;
    for (const char* t : {"sky1", "water", "+0water", "clip"}) EXPECT_FALSE(isLiquidTexture(t)) << t;
}

TEST(MapCompile, FaceTexturesDecideFaceVisibility) {
    // One brush: sky on top, hint below, caulk and clip on two sides, ordinary walls elsewhere.
    std::string b = cube(0, 0, 0, "wall");
    const auto retexture = [&](int faceLine, const std::string& tex) {
        std::size_t at = 0;
        for (int i = 0; i <= faceLine; ++i) at = b.find("wall", at + 1);
        b.replace(at, 4, tex);
    };
    retexture(2, "hint");        // the z = 0 face
    retexture(3, "sky4");        // the z = 64 face
    retexture(0, "common/caulk");
    retexture(1, "PLAYERCLIP");
    const Level l = compile(entity("\"classname\" \"worldspawn\"", b));
    ASSERT_EQ(l.brushes.size(), 1u);
    const LevelBrush& br = l.brushes[0];
    EXPECT_TRUE(br.solid);
    EXPECT_TRUE(br.visible);
    int shown = 0;
    for (const auto& p : br.faces) {
        const bool expectVisible = p.texture == "wall" || p.texture == "sky4";
        EXPECT_EQ(p.visible, expectVisible) << p.texture;
        shown += p.visible;
    }
    EXPECT_EQ(shown, 3);  // sky + two walls
}

TEST(MapCompile, PointEntityKeys) {
    const std::string text =
        entity("\"classname\" \"worldspawn\"", cube(0, 0, 0)) +
        entity("\"classname\" \"info_player_coop\"\n\"origin\" \"0 0 100\"") +
        entity("\"classname\" \"info_player_start\"\n\"origin\" \"10 -20 30.5\"\n\"angle\" \"-1\"") +
        entity("\"classname\" \"info_player_start\"\n\"origin\" \"999 0 0\"") +  // only the first counts
        entity("\"classname\" \"light_torch_small_walltorch\"\n\"origin\" \"0 0 0\"\n\"_light\" \"200\"\n\"color\" \"1 0.5 0.25\"") +
        entity("\"classname\" \"light\"\n\"origin\" \"0 0 0\"") +
        entity("\"classname\" \"misc_model\"\n\"origin\" \"0 0 0\"\n\"model\" \"a.mesh\"\n\"modelscale\" \"0.5\"\n"
               "\"angles\" \"10 180 5\"") +
        entity("\"classname\" \"misc_model\"\n\"origin\" \"0 0 0\"\n\"model\" \"b.mesh\"");
    std::vector<std::string> warnings;
    const Level l = compile(text, &warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    ASSERT_TRUE(l.hasPlayerStart);
    // Quake (10, -20, 30.5 - 24) / 32 -> (x, z, -y).
    EXPECT_DOUBLE_EQ(l.playerStart.x, 10.0 / 32);
    EXPECT_DOUBLE_EQ(l.playerStart.y, 6.5 / 32);
    EXPECT_DOUBLE_EQ(l.playerStart.z, 20.0 / 32);
    EXPECT_NEAR(l.playerStartYaw, -kPi / 2, 1e-12);  // angle -1 ("up") counts as yaw 0
    // The player start entity keeps its centre (not the feet) as its origin.
    EXPECT_DOUBLE_EQ(l.entities[2].origin.y, 30.5 / 32);

    ASSERT_EQ(l.lights.size(), 2u);
    EXPECT_DOUBLE_EQ(l.lights[0].intensity, 200);
    EXPECT_DOUBLE_EQ(l.lights[0].radius, 200.0 / 32);
    EXPECT_DOUBLE_EQ(l.lights[0].colour.y, 0.5);  // 0..1 triplet kept as is
    EXPECT_DOUBLE_EQ(l.lights[1].intensity, 300);  // Quake's default
    EXPECT_DOUBLE_EQ(l.lights[1].colour.x, 1);

    ASSERT_EQ(l.models.size(), 2u);
    EXPECT_DOUBLE_EQ(l.models[0].scale, 0.5);
    EXPECT_NEAR(l.models[0].yaw, kPi, 1e-12);  // from the yaw of "angles", plus the model frame's pi/2
    EXPECT_DOUBLE_EQ(l.models[1].scale, 1);
    EXPECT_NEAR(l.models[1].yaw, 0, 1e-12);
    EXPECT_TRUE(l.unknownClassnames.empty());
}

TEST(MapCompile, MalformedKeysWarnAndFallBack) {
    const std::string text = entity("\"classname\" \"worldspawn\"\n\"units_per_metre\" \"32\"", cube(0, 0, 0)) +
                             entity("\"classname\" \"light\"\n\"origin\" \"1 2\"") +
                             entity("\"classname\" \"light\"\n\"origin\" \"0 0 0\"\n\"light\" \"bright\"") +
                             entity("\"origin\" \"0 0 0\"");
    std::vector<std::string> warnings;
    const Level l = compile(text, &warnings);
    EXPECT_DOUBLE_EQ(l.unitsPerMetre, 32);
    ASSERT_EQ(l.lights.size(), 1u);  // the light without a usable origin is dropped
    EXPECT_DOUBLE_EQ(l.lights[0].intensity, 300);
    const auto has = [&](const std::string& what) {
        for (const auto& w : warnings)
            if (w.find(what) != std::string::npos) return true;
        return false;
    };
    EXPECT_TRUE(has("t.map:13: 'origin' value '1 2' is not three numbers"));
    EXPECT_TRUE(has("t.map:17: 'light' value 'bright' is not a number"));
    EXPECT_TRUE(has("t.map:22: entity without a classname"));
    EXPECT_TRUE(has("no info_player_start"));
    EXPECT_TRUE(l.unknownClassnames.empty());
}

TEST(MapCompile, NonPositiveTextureSizeFallsBackTo64) {
    CompileOptions o;
    o.textureSize = [](const std::string&) { return std::make_pair(0, -5); };
    const Level l = compileLevel(parseMap(entity("\"classname\" \"worldspawn\"", cube(0, 0, 0)), "t.map"), o);
    for (const auto& p : l.brushes.at(0).faces)
        for (const auto& v : p.vertices) {
            EXPECT_TRUE(std::isfinite(v.u) && std::isfinite(v.v));
            EXPECT_NEAR(v.u, v.position.x * 32 / 64, 1e-9);
        }
}
