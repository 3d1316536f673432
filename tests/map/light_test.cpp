// Light entities and worldspawn lighting keys (map_lights.cpp), Quake's falloff maths
// (quake_light.cpp) against the formulas written out by hand, the light grid level.frag reads
// (render/light_grid.cpp) and the chunk cut (render/level_chunks.cpp).
#include <gtest/gtest.h>

#include "level/level_shared.h"
#include "map/map_compile.h"
#include "map/map_lights.h"
#include "map/quake_light.h"
#include "render/level_chunks.h"
#include "render/light_grid.h"
#include "test_maps.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <iostream>

using namespace obscura;
using namespace obscura::map;
using testdata::cube;
using testdata::entity;

namespace {
constexpr double kPi = 3.14159265358979323846;

using testdata::compile;

const std::string kWorld = entity("\"classname\" \"worldspawn\"", cube(-512, -512, -64, "floor", 1024)) +
                           entity("\"classname\" \"info_player_start\"\n\"origin\" \"0 0 24\"");  // lines 1-15

std::string light(const std::string& keys, const std::string& origin = "0 0 64") {
    return entity("\"classname\" \"light\"\n\"origin\" \"" + origin + "\"\n" + keys);
}

bool has(const std::vector<std::string>& warnings, const std::string& what) {
    for (const auto& w : warnings)
        if (w.find(what) != std::string::npos) return true;
    return false;
}
}  // namespace

TEST(QuakeLight, FormulasMatchEricwToolsAtKnownDistances) {
    LevelLight l;
    l.intensity = 300;
    l.unitsPerMetreScaled = 32;
    l.radius = 300.0 / 32;
    // delay 0: (value - x) / 200, x in map units.
    for (double units : {0.0, 64.0, 150.0, 299.0}) EXPECT_NEAR(lightAtDistance(l, units / 32), (300 - units) / 200, 1e-12) << units;
    EXPECT_EQ(lightAtDistance(l, 301.0 / 32), 0.0);
    // wait 2 doubles the distance (the reach halves).
    l.unitsPerMetreScaled = 64;
    l.radius = 300.0 / 64;
    EXPECT_NEAR(lightAtDistance(l, 64.0 / 32), (300 - 128) / 200.0, 1e-12);
    // delay 1: value * 128 / x, less the gate.
    l.formula = LightFormula::Inverse;
    l.unitsPerMetreScaled = 32;
    EXPECT_NEAR(lightAtDistance(l, 256.0 / 32), 300 * 128 / 256.0 / 200 - kLightGate, 1e-12);
    // delay 2: value * 128^2 / x^2; inside kMinInverseDistance it stays at its value there.
    l.formula = LightFormula::InverseSquare;
    EXPECT_NEAR(lightAtDistance(l, 256.0 / 32), 300 * 128.0 * 128 / (256.0 * 256) / 200 - kLightGate, 1e-12);
    EXPECT_NEAR(lightAtDistance(l, 1.0 / 32), lightAtDistance(l, kMinInverseDistance / 32), 1e-12);
    // The gate: where the light falls to it, the reach.
    EXPECT_NEAR(lightAtDistance(l, lightReach(l, 1e9)), 0.0, 1e-9);
    EXPECT_NEAR(lightReach(l, 1e9), 128 * std::sqrt(1.5 / kLightGate) / 32, 1e-9);
    // delay 5: value * 128^2 / (x + 128)^2.
    l.formula = LightFormula::InverseSquareA;
    EXPECT_NEAR(lightAtDistance(l, 128.0 / 32), 300 * 128.0 * 128 / (256.0 * 256) / 200 - kLightGate, 1e-12);
    // delay 3: the value anywhere.
    l.formula = LightFormula::None;
    EXPECT_NEAR(lightAtDistance(l, 1000), 1.5, 1e-12);
    // A negative light subtracts.
    l.formula = LightFormula::Linear;
    l.intensity = -300;
    l.radius = 300.0 / 32;
    EXPECT_NEAR(lightAtDistance(l, 100.0 / 32), -200 / 200.0, 1e-12);
}

TEST(QuakeLight, AngleAndConeFactors) {
    LevelLight l;
    EXPECT_DOUBLE_EQ(angleFactor(l, 1), 1);
    EXPECT_DOUBLE_EQ(angleFactor(l, 0.5), 0.75);  // Quake's default _anglescale 0.5
    EXPECT_DOUBLE_EQ(angleFactor(l, -0.1), 0);    // behind the face
    l.angleScale = 1;
    EXPECT_DOUBLE_EQ(angleFactor(l, 0.5), 0.5);  // Lambert
    l.spot = true;
    l.spotCosOuter = std::cos(20 * kPi / 180);
    l.spotCosInner = std::cos(10 * kPi / 180);
    EXPECT_DOUBLE_EQ(spotFactor(l, 1), 1);
    EXPECT_DOUBLE_EQ(spotFactor(l, std::cos(25 * kPi / 180)), 0);
    EXPECT_NEAR(spotFactor(l, (l.spotCosOuter + l.spotCosInner) / 2), 0.5, 1e-12);  // linear in the cosine
}

TEST(MapLights, KeysBecomeFormulaReachSpotAndColour) {
    const std::string text =
        kWorld + light("\"light\" \"200\"\n\"wait\" \"2\"\n\"_color\" \"255 128 0\"") +
        light("\"light\" \"300\"\n\"delay\" \"2\"\n\"_anglescale\" \"1\"") +
        light("\"light\" \"300\"\n\"_falloff\" \"640\"\n\"wait\" \"4\"") +
        light("\"light\" \"300\"\n\"target\" \"spot\"\n\"_softangle\" \"10\"", "0 0 128") +
        entity("\"classname\" \"info_null\"\n\"targetname\" \"spot\"\n\"origin\" \"128 0 0\"") +
        light("\"light\" \"300\"\n\"mangle\" \"90 -90 0\"\n\"angle\" \"60\"") +
        entity("\"classname\" \"light_torch_small_walltorch\"\n\"origin\" \"0 64 64\"");
    std::vector<std::string> warnings;
    const Level l = compile(text, &warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    ASSERT_EQ(l.lights.size(), 6u);
    EXPECT_EQ(l.lights[0].formula, LightFormula::Linear);
    EXPECT_DOUBLE_EQ(l.lights[0].radius, 200.0 / 64);  // wait 2 halves the reach
    EXPECT_DOUBLE_EQ(l.lights[0].colour.y, 128.0 / 255);
    EXPECT_FALSE(l.lights[0].spot);
    EXPECT_EQ(l.lights[1].formula, LightFormula::InverseSquare);
    EXPECT_DOUBLE_EQ(l.lights[1].angleScale, 1);
    EXPECT_NEAR(l.lights[1].radius, lightReach(l.lights[1], 1e9), 1e-9);
    EXPECT_DOUBLE_EQ(l.lights[2].radius, 640.0 / 32);  // _falloff replaces the reach; wait ignored
    // Aimed by target at (128, 0, 0) from (0, 0, 128): down and east, 45 degrees.
    ASSERT_TRUE(l.lights[3].spot);
    EXPECT_NEAR(l.lights[3].spotDirection.x, std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(l.lights[3].spotDirection.y, -std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(l.lights[3].spotCosOuter, std::cos(20 * kPi / 180), 1e-12);  // ericw-tools' 40 degree cone
    EXPECT_NEAR(l.lights[3].spotCosInner, std::cos(5 * kPi / 180), 1e-12);
    // mangle pitch -90: straight down; `angle` is the cone.
    ASSERT_TRUE(l.lights[4].spot);
    EXPECT_NEAR(l.lights[4].spotDirection.y, -1, 1e-12);
    EXPECT_NEAR(l.lights[4].spotCosOuter, std::cos(30 * kPi / 180), 1e-12);
    EXPECT_DOUBLE_EQ(l.lights[5].intensity, 300);  // any light* class, Quake's default value
    EXPECT_TRUE(l.lighting.hasLightEntities);
}

TEST(MapLights, BadKeysWarnWithFileAndLineAndTheLevelLoads) {
    const std::string text = kWorld +                                                    // lines 1-15 (the entity lines are their openings)
                             light("\"delay\" \"slow\"") +                               // 16
                             light("\"_cone\" \"400\"\n\"mangle\" \"0 -90 0\"") +        // 21
                             light("\"target\" \"nobody\"") +                            // 27
                             light("\"wait\" \"-1\"\n\"delay\" \"9\"") +                 // 32
                             light("\"_color\" \"red\"\n\"_softangle\" \"50\"\n\"mangle\" \"0 -90 0\"");  // 38
    std::vector<std::string> warnings;
    const Level l = compile(text, &warnings);
    ASSERT_EQ(l.lights.size(), 5u);
    EXPECT_TRUE(has(warnings, "t.map:16: 'delay' value 'slow' is not a number; using 0")) << warnings.size();
    EXPECT_TRUE(has(warnings, "t.map:21: '_cone' value '400' is out of range, expected 0 to 180; using 40"));
    EXPECT_TRUE(has(warnings, "t.map:27: 'target' value 'nobody' names no entity with an origin; not a spotlight"));
    EXPECT_TRUE(has(warnings, "t.map:32: 'wait' value '-1' is out of range"));
    EXPECT_TRUE(has(warnings, "t.map:32: 'delay' value '9' is out of range"));
    EXPECT_TRUE(has(warnings, "t.map:38: '_color' value 'red' is not three numbers"));
    EXPECT_TRUE(has(warnings, "t.map:38: '_softangle' 50 is not smaller than the cone 40; a hard edge"));
    EXPECT_EQ(l.lights[0].formula, LightFormula::Linear);
    EXPECT_NEAR(l.lights[1].spotCosOuter, std::cos(20 * kPi / 180), 1e-12);
    EXPECT_FALSE(l.lights[2].spot);
    EXPECT_DOUBLE_EQ(l.lights[3].unitsPerMetreScaled, 32);
    EXPECT_DOUBLE_EQ(l.lights[4].spotCosInner, l.lights[4].spotCosOuter);
}

TEST(MapLights, WorldspawnAmbientAndSunAliases) {
    const auto world = [](const std::string& keys) {
        return compile(entity("\"classname\" \"worldspawn\"\n" + keys, cube(0, 0, -64))).lighting;
    };
    LevelLightingKeys k = world("\"light\" \"40\"\n\"_minlight_color\" \"255 0 0\"");
    EXPECT_TRUE(k.hasMinlight);
    EXPECT_DOUBLE_EQ(k.minlight, 40);
    EXPECT_DOUBLE_EQ(k.minlightColour.y, 0);
    EXPECT_FALSE(k.hasLightEntities);
    EXPECT_DOUBLE_EQ(world("\"_minlight\" \"25\"").minlight, 25);
    // Sun direction: each spelling; yaw 0 pitch -45 travels east (+x) and down.
    for (const char* key : {"_sunlight_mangle", "_sun_mangle", "_sun_angle"}) {
        k = world("\"_sunlight\" \"200\"\n\"" + std::string(key) + "\" \"0 -45 0\"\n\"_sunlight_color\" \"0 0 255\"");
        EXPECT_NEAR(k.sunTravel.x, std::sqrt(0.5), 1e-12) << key;
        EXPECT_NEAR(k.sunTravel.y, -std::sqrt(0.5), 1e-12) << key;
        EXPECT_DOUBLE_EQ(k.sunColour.z, 1) << key;
    }
    k = world("\"_sunlight2\" \"150\"\n\"_sunlight_color2\" \"0 255 0\"\n\"_sunlight3\" \"20\"");
    EXPECT_DOUBLE_EQ(k.dome, 150);
    EXPECT_DOUBLE_EQ(k.domeColour.x, 0);
    EXPECT_DOUBLE_EQ(k.domeBelow, 20);
    k = world("\"_ambient_sky\" \"0.4 0.5 0.6\"\n\"_ambient_ground\" \"0.1 0.2 0.3\"");
    EXPECT_TRUE(k.hasAmbient);
    EXPECT_DOUBLE_EQ(k.ambientSky.z, 0.6);
    EXPECT_DOUBLE_EQ(k.ambientGround.x, 0.1);
    // A `_sun` light entity is the sun when worldspawn has none, aimed at its target; it casts nothing itself.
    const Level l = compile(entity("\"classname\" \"worldspawn\"", cube(0, 0, -64)) +
                            light("\"_sun\" \"1\"\n\"light\" \"150\"\n\"target\" \"s\"", "0 0 100") +
                            entity("\"classname\" \"info_null\"\n\"targetname\" \"s\"\n\"origin\" \"0 0 0\""));
    EXPECT_TRUE(l.lights.empty());
    EXPECT_DOUBLE_EQ(l.lighting.sunlight, 150);
    EXPECT_NEAR(l.lighting.sunTravel.y, -1, 1e-12);
}

TEST(LevelChunks, ChunksCutUnderALightLimitKeepEveryFace) {
    // One 16 m floor face (one chunk) under 40 lights on a 2 m grid, cut to at most 7 a chunk.
    const Level level = compile(entity("\"classname\" \"worldspawn\"", cube(0, 0, -32, "floor", 512)));
    std::vector<render::LightSphere> lights;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 5; ++j) lights.push_back({{1.0 + 2 * i, 0.5, -1.0 - 2 * j - 3}, 1.875});
    const std::size_t limit = 7;
    render::ChunkStats stats;
    const auto chunks = render::buildChunks(level, 16.0, lights, limit, [](const std::string&) { return false; }, &stats);
    EXPECT_GT(stats.split, 0u);
    EXPECT_EQ(stats.overfull, 0u);
    double area = 0, original = 0;
    const auto polyArea = [](const std::vector<LevelVertex>& v) {
        Vec3 s;
        for (std::size_t i = 1; i + 1 < v.size(); ++i) s += cross(v[i].position - v[0].position, v[i + 1].position - v[0].position);
        return length(s) / 2;
    };
    for (const auto& c : chunks) {
        EXPECT_LE(c.lightsReaching, limit);
        EXPECT_EQ(c.lightsReaching, render::lightsReaching(c.centre, c.radius, lights));
        for (const auto& p : c.polygons) area += polyArea(p.vertices);
    }
    for (const auto& b : level.brushes)
        for (const auto& f : b.faces) original += polyArea(f.vertices);
    EXPECT_NEAR(area, original, 1e-6 * original);  // every face, clipped, still all there
}

namespace {
// Every light that adds anything at `p` is listed for p's cell (points outside the grid, which
// spans the level's brushes and lights, hold no surface: skipped).
void expectEveryReachingLightListed(const Level& level, const render::LightGrid& grid, const Vec3& p) {
    const Vec3 q = (p - grid.origin) / grid.cell;
    if (q.x < 0 || q.y < 0 || q.z < 0 || q.x >= grid.nx || q.y >= grid.ny || q.z >= grid.nz) return;
    const std::vector<int> listed = grid.lightsAt(p);
    for (std::size_t i = 0; i < level.lights.size(); ++i) {
        if (length(level.lights[i].position - p) >= lightReach(level.lights[i], 1e9)) continue;
        EXPECT_NE(std::find(listed.begin(), listed.end(), static_cast<int>(i)), listed.end())
            << "light " << i << " reaches (" << p.x << ", " << p.y << ", " << p.z << ") but is not listed";
    }
}
}  // namespace

TEST(LightGrid, EveryLightThatReachesAPointIsListedForItsCell) {
    // 40 lamps over one face (tests/lighting/levels/many_lights.map): more than OGRE's 8 a pass.
    const Level level = loadLevel(std::string(OBSCURA_SOURCE_DIR) + "/tests/lighting/levels/many_lights.map");
    ASSERT_EQ(level.lights.size(), 40u);
    const render::LightGrid grid = render::buildLightGrid(level);
    for (double x = 0.05; x < 16; x += 0.25)
        for (double z = -0.05; z > -16; z -= 0.25) expectEveryReachingLightListed(level, grid, {x, 0.0, z});
    // The packed light: position and reach, colour x value / 200, the formula.
    const float* t = &grid.texels[0];
    EXPECT_FLOAT_EQ(t[0], static_cast<float>(level.lights[0].position.x));
    EXPECT_FLOAT_EQ(t[3], static_cast<float>(level.lights[0].radius));
    EXPECT_FLOAT_EQ(t[4], static_cast<float>(28.0 / 200));
    EXPECT_FLOAT_EQ(t[7], 0.0f);  // linear
}

TEST(LightGrid, LibreQuakeE3m4) {
    const std::filesystem::path path = std::filesystem::path(OBSCURA_THIRD_PARTY_DIR) / "librequake/e3m4.map";
    const Level level = loadLevel(path.string());
    const render::LightGrid grid = render::buildLightGrid(level);
    std::cout << "e3m4: " << level.lights.size() << " lights, grid " << grid.nx << " x " << grid.ny << " x " << grid.nz << " cells of "
              << grid.cell << " m, " << grid.indices << " listings, at most " << grid.mostInACell << " lights a cell, "
              << grid.rows() << " texture rows\n";
    EXPECT_LE(static_cast<std::size_t>(grid.nx) * grid.ny * grid.nz, render::kMaxLightGridCells);
    // Points near every light (its foot and halfway to its reach, four ways).
    for (const auto& l : level.lights) {
        const double r = lightReach(l, 1e9) * 0.5;
        for (const Vec3& d : {Vec3{0, -r, 0}, Vec3{r, 0, 0}, Vec3{0, 0, r}, Vec3{-r, 0, -r * 0.5}})
            expectEveryReachingLightListed(level, grid, l.position + d);
    }
}

TEST(LightGrid, TheLayoutTheShaderReadsIsTheOneThePackerWrites) {
    EXPECT_EQ(LEVEL_LIGHT_TEXELS, render::kLightTexels);
    EXPECT_EQ(LEVEL_LIGHT_SPOT_FLAG, render::kSpotFlag);
    EXPECT_EQ(LEVEL_LIGHT_ROW, render::kLightGridWidth);
    EXPECT_EQ(LEVEL_INVERSE_SCALE, kInverseLightScale);
    EXPECT_EQ(LEVEL_MIN_INVERSE_DISTANCE, kMinInverseDistance);
    EXPECT_EQ(LEVEL_LIGHT_INVERSE_SQUARE_A, static_cast<int>(LightFormula::InverseSquareA));
    EXPECT_EQ(LEVEL_LIGHT_LOCAL_MINIMUM, static_cast<int>(LightFormula::LocalMinimum));
}

// env_ambient: its brushes' box, its keys, and the factor the lighting pass mirrors.
TEST(AmbientAreas, EnvAmbientBecomesAnInvisibleNonSolidBoxWithItsScale) {
    std::vector<std::string> warnings;
    // A 64-unit cube from (0, 0, 0) Quake = 2 m: world x 0..2, y (up) 0..2, z -2..0.
    const Level level = compile(kWorld + entity("\"classname\" \"env_ambient\"\n\"ambient\" \"0.25\"\n\"blend\" \"0.5\"", cube(0, 0, 0)),
                                &warnings);
    ASSERT_EQ(level.ambientAreas.size(), 1u);
    const AmbientArea& a = level.ambientAreas[0];
    EXPECT_NEAR(a.box.min.x, 0, 1e-9);
    EXPECT_NEAR(a.box.max.y, 2, 1e-9);
    EXPECT_NEAR(a.box.min.z, -2, 1e-9);
    EXPECT_DOUBLE_EQ(a.scale, 0.25);
    EXPECT_DOUBLE_EQ(a.blend, 0.5);
    for (const LevelBrush& b : level.brushes)
        if (b.entityIndex == 2) EXPECT_FALSE(b.solid || b.visible);  // a volume, like a trigger's
    EXPECT_TRUE(warnings.empty()) << warnings.front();
}

TEST(AmbientAreas, BadKeysWarnWithFileAndLineAndNoBrushesIsSkipped) {
    std::vector<std::string> warnings;
    const std::string text = kWorld + entity("\"classname\" \"env_ambient\"\n\"ambient\" \"2\"\n\"blend\" \"soft\"", cube(0, 0, 0)) +
                             entity("\"classname\" \"env_ambient\"");
    const Level level = compile(text, &warnings);
    ASSERT_EQ(level.ambientAreas.size(), 1u);
    EXPECT_DOUBLE_EQ(level.ambientAreas[0].scale, 0.1);  // out of range: the default
    EXPECT_DOUBLE_EQ(level.ambientAreas[0].blend, 0);
    EXPECT_TRUE(has(warnings, "t.map:16: 'ambient' value '2' is out of range, expected 0 to 1")) << testing::PrintToString(warnings);
    EXPECT_TRUE(has(warnings, "t.map:16: 'blend' value 'soft' is not a number"));
    EXPECT_TRUE(has(warnings, "env_ambient has no brushes; skipped"));
}

TEST(AmbientAreas, TheFactorIsTheScaleInsideOneOutsideAndBlendsAcrossTheFace) {
    AmbientArea hard;
    hard.box.extend({0, 0, 0});
    hard.box.extend({4, 3, 4});
    hard.scale = 0.2;
    EXPECT_NEAR(ambientScaleAt({hard}, {2, 1, 2}), 0.2, 1e-12);
    EXPECT_NEAR(ambientScaleAt({hard}, {2, 1, 4.01}), 0.2, 1e-12);  // a surface just outside the face: on it
    EXPECT_DOUBLE_EQ(ambientScaleAt({hard}, {2, 1, 4.05}), 1.0);
    EXPECT_DOUBLE_EQ(ambientScaleAt({}, {2, 1, 2}), 1.0);
    AmbientArea soft = hard;
    soft.blend = 1;
    const double onFace = 1 + (0.2 - 1) * (0.5 + kAmbientAreaGrace);
    EXPECT_NEAR(ambientScaleAt({soft}, {4 + kAmbientAreaGrace, 1, 2}), 0.6, 1e-12);  // half way at the face (and its grace)
    EXPECT_NEAR(ambientScaleAt({soft}, {4, 1, 2}), onFace, 1e-12);
    EXPECT_NEAR(ambientScaleAt({soft}, {2, 1, 2}), 0.2, 1e-12);
    EXPECT_DOUBLE_EQ(ambientScaleAt({soft}, {2, 1, 6}), 1.0);
    AmbientArea darker = hard;
    darker.scale = 0.05;
    EXPECT_NEAR(ambientScaleAt({hard, darker}, {2, 1, 2}), 0.05, 1e-12);  // overlaps: the darkest, not the product
}
