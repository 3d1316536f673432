// Hostile and out-of-range .map input: every case is a MapError naming file and line (never an
// OGRE assertion later, an unbounded read or a minute of brush clipping), and error text stays short.
#include <gtest/gtest.h>

#include "map/input_file.h"
#include "map/map_compile.h"
#include "test_maps.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace obscura;
using namespace obscura::map;
using testdata::cube;
using testdata::entity;

namespace fs = std::filesystem;

namespace {
std::string parseError(const std::string& text) {
    try {
        parseMap(text, "t.map");
    } catch (const MapError& e) {
        return e.what();
    }
    return "";
}

std::string compileError(const std::string& text) {
    try {
        compileLevel(parseMap(text, "t.map"));
    } catch (const MapError& e) {
        return e.what();
    }
    return "";
}

std::string loadError(const std::string& path) {
    try {
        loadMapFile(path);
    } catch (const MapError& e) {
        return e.what();
    }
    return "";
}

const std::string kWorld = entity("\"classname\" \"worldspawn\"", cube(0, 0, 0));

std::string model(const std::string& keys) {
    return entity("\"classname\" \"misc_model\"\n\"origin\" \"0 0 0\"\n\"model\" \"a.mesh\"\n" + keys);
}

// A brush of n faces, all planes tangent to a sphere of radius 64 (a golden-spiral set of
// normals): every face is clipped by every other one, the brush compiler's worst case.
std::string manyFacedBrush(int n) {
    std::string b = "{\n";
    const auto num = [](double v) { return std::to_string(v); };
    for (int i = 0; i < n; ++i) {
        const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z), phi = i * 2.39996322972865332;
        const Vec3 nrm{r * std::cos(phi), r * std::sin(phi), z};
        const Vec3 t1 = normalize(cross(nrm, std::fabs(nrm.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0})) * 16.0;
        const Vec3 t2 = cross(t1, nrm);  // cross(t2, t1) = |t1|^2 n: the plane faces out
        const Vec3 p1 = nrm * 64.0, p2 = p1 + t1, p3 = p1 + t2;
        b += "( " + num(p1.x) + " " + num(p1.y) + " " + num(p1.z) + " ) ( " + num(p2.x) + " " + num(p2.y) + " " + num(p2.z) +
             " ) ( " + num(p3.x) + " " + num(p3.y) + " " + num(p3.z) + " ) t 0 0 0 1 1\n";
    }
    return b + "}\n";
}
}  // namespace

TEST(MapLimits, DirectoryDeviceAndOversizedFilesAreRefusedByName) {
    EXPECT_EQ(loadError("/dev/zero"), "/dev/zero: is a device, expected a map file");
    const fs::path dir = fs::path(testing::TempDir()) / "a_folder.map";
    fs::create_directories(dir);
    EXPECT_EQ(loadError(dir.string()), dir.string() + ": is a directory, expected a map file");
    // A sparse file one byte over the cap: refused before anything is read.
    const fs::path big = fs::path(testing::TempDir()) / "huge.map";
    std::ofstream(big.string()).close();
    fs::resize_file(big, kMaxMapFileBytes + 1);
    EXPECT_EQ(loadError(big.string()), big.string() + ": map file is 67108865 bytes, more than the 64 MiB limit");
    fs::remove(big);
}

TEST(MapLimits, FacesPerBrushAreCapped) {
    // At the cap it compiles (quickly); one more face is an error naming the brush.
    const auto t0 = std::chrono::steady_clock::now();
    const std::string ok = entity("\"classname\" \"worldspawn\"", manyFacedBrush(static_cast<int>(kMaxFacesPerBrush)));
    std::vector<std::string> warnings;
    const Level l = compileLevel(parseMap(ok, "t.map"), {}, &warnings);
    ASSERT_EQ(l.brushes.size(), 1u) << (warnings.empty() ? "" : warnings[0]);
    EXPECT_EQ(l.brushes[0].faces.size(), kMaxFacesPerBrush);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LT(seconds, 1.0);
    std::printf("a %zu-face brush: %.1f ms\n", kMaxFacesPerBrush, seconds * 1e3);
    const std::string e = parseError(entity("\"classname\" \"worldspawn\"", manyFacedBrush(static_cast<int>(kMaxFacesPerBrush) + 1)));
    EXPECT_EQ(e, "t.map:132:1: brush opened at line 3 has more than 128 faces (the limit per brush)");
}

TEST(MapLimits, BrushesEntitiesAndKeysAreCapped) {
    std::string brushes = "{\n";
    for (std::size_t i = 0; i <= kMaxBrushesPerMap; ++i) brushes += "{ }\n";
    EXPECT_EQ(parseError(brushes + "}\n"), "t.map:65538:1: more than 65536 brushes in the map (the limit per level)");
    std::string entities;
    for (std::size_t i = 0; i <= kMaxEntitiesPerMap; ++i) entities += "{ }\n";
    EXPECT_EQ(parseError(entities), "t.map:65537:1: more than 65536 entities in the map (the limit per level)");
    std::string keys = "{\n";
    for (std::size_t i = 0; i <= kMaxKeysPerEntity; ++i) keys += "\"k" + std::to_string(i) + "\" \"v\"\n";
    EXPECT_EQ(parseError(keys + "}\n"), "t.map:1026:1: entity opened at line 1 has more than 1024 keys (the limit per entity)");
}

TEST(MapLimits, ErrorsQuoteLongTokensShortAndEscapeRawBytes) {
    const std::string longNumber(10'000'000, '7');
    const std::string e = parseError("{\n{\n( " + longNumber + "x 0 0 ) ( 0 0 0 ) ( 0 0 0 ) t 0 0 0 1 1\n}\n}\n");
    EXPECT_LT(e.size(), 200u) << e.size();
    EXPECT_NE(e.find("t.map:3:3: '7777"), std::string::npos) << e;
    EXPECT_NE(e.find("... (10000001 bytes)' is not a number (x coordinate)"), std::string::npos) << e;
    EXPECT_EQ(parseError("{\n\x01\x7f\n}\n"), "t.map:2:1: expected '\"', '{' or '}' in an entity, found '\\x01'");
    EXPECT_EQ(errorText("a\x1b[31mb\xff"), "a\\x1b[31mb\\xff");
    EXPECT_EQ(errorText(std::string(100, 'a'), 4), "aaaa... (100 bytes)");
}

TEST(MapLimits, ModelScaleMustBePositiveAndBounded) {
    for (const char* bad : {"0", "-1", "1e-310", "1e39", "-1e39", "1e400", "nan", "big", "0.0009", "1001"}) {
        const std::string e = compileError(kWorld + model("\"scale\" \"" + std::string(bad) + "\""));
        EXPECT_EQ(e, "t.map:12: misc_model 'scale' value '" + std::string(bad) + "' is not a number from 0.001 to 1000") << bad;
    }
    EXPECT_EQ(compileError(kWorld + model("\"modelscale\" \"0\"")),
              "t.map:12: misc_model 'modelscale' value '0' is not a number from 0.001 to 1000");
    const Level l = compileLevel(parseMap(kWorld + model("\"scale\" \"0.001\"") + model("\"scale\" \"1000\""), "t.map"));
    ASSERT_EQ(l.models.size(), 2u);
    EXPECT_DOUBLE_EQ(l.models[0].scale, 0.001);
    EXPECT_EQ(l.models[1].pos.line, 18);  // the entity's line travels with the model (for later errors)
    EXPECT_NE(compileError(kWorld + entity("\"classname\" \"misc_model\"\n\"model\" \"" + std::string(300, 'm') + "\""))
                  .find("t.map:12: misc_model 'model' value 'mmm"),
              std::string::npos);
}

TEST(MapLimits, PlacedEntitiesMustLieNearTheLevel) {
    // The 64-unit cube is 2 m; the margin is 100 m (3,200 units) on each side.
    const std::string far = entity("\"classname\" \"info_player_start\"\n\"origin\" \"1e10 0 24\"");
    EXPECT_EQ(compileError(kWorld + far),
              "t.map:12: info_player_start origin '1e10 0 24' is (3.125e+08, 0.75, 0) m in the world, outside the level's "
              "brushes plus 100 m (-100, -100, -102) to (102, 102, 100)");
    const std::string farModel = entity("\"classname\" \"misc_model\"\n\"origin\" \"0 -4000 0\"\n\"model\" \"a.mesh\"");
    EXPECT_NE(compileError(kWorld + farModel).find("t.map:12: misc_model origin '0 -4000 0' is (0, 0, 125) m"), std::string::npos);
    // Just inside the margin, and a level of models alone (the margin around the origin), load.
    EXPECT_NO_THROW(compileLevel(parseMap(kWorld + entity("\"classname\" \"info_player_start\"\n\"origin\" \"3200 0 0\""), "t.map")));
    EXPECT_NO_THROW(compileLevel(parseMap(entity("\"classname\" \"worldspawn\"") + entity("\"classname\" \"info_player_start\"\n\"origin\" \"0 0 400\""), "t.map")));
}

TEST(MapLimits, UnitsPerMetreAndLightValuesAreRanged) {
    EXPECT_EQ(compileError(entity("\"classname\" \"worldspawn\"\n\"units_per_metre\" \"zero\"", cube(0, 0, 0))),
              "t.map:1: worldspawn 'units_per_metre' value 'zero' is not a number from 1 to 1024");
    EXPECT_EQ(compileError(entity("\"classname\" \"worldspawn\"\n\"units_per_metre\" \"1e-300\"", cube(0, 0, 0))),
              "t.map:1: worldspawn 'units_per_metre' value '1e-300' is not a number from 1 to 1024");
    CompileOptions o;
    o.unitsPerMetre = 0.5;
    try {
        compileLevel(parseMap(kWorld, "t.map"), o);
        FAIL();
    } catch (const MapError& e) {
        EXPECT_STREQ(e.what(), "t.map: units per metre 0.5 is out of range, expected 1 to 1024");
    }
    EXPECT_EQ(compileError(kWorld + entity("\"classname\" \"light\"\n\"origin\" \"0 0 0\"\n\"light\" \"1e300\"")),
              "t.map:12: light 'light' value '1e300' is out of range, expected -1000000 to 1000000");
}
