// The light bake (engine_ext/lightbake) on small levels: a lamp stops at a wall, a sealed room
// under sun and sky is dark, an open one is not, and the result is the same on any thread count.
#include "bake_levels.h"

#include <gtest/gtest.h>

using namespace obscura;
using namespace obscura::lightbake;
using namespace obscura::lightbake::testdata;

namespace {
const std::string kSunAndSky = "\"classname\" \"worldspawn\"\n\"_sunlight\" \"200\"\n\"_sunlight2\" \"150\"\n\"_sunlight_mangle\" \"0 -60 0\"\n";
const Vec3 kUp{0, 1, 0};

struct Sample {
    float direct[4], indirect[3];
};
Sample sampleFloor(const LightBake& bake, const map::Level& level, double x, double y) {
    const Vec3 p = metres(x, y, 0);
    const long c = chartAt(bake, level, p, kUp);
    EXPECT_GE(c, 0) << "no floor chart at " << x << " " << y;
    Sample s{};
    if (c >= 0) sampleLightmap(bake, static_cast<std::size_t>(c), p, s.direct, s.indirect);
    return s;
}

// Two rooms 8 x 8 x 4 m side by side, sharing a 0.25 m (8-unit) wall at x = 256..264; a lamp in the
// first, 0.5 m from the wall. `roof`: sealed; else both rooms open to the sky.
std::string twoRooms(bool roof, const std::string& worldspawn) {
    const int h = 128, t = 16;
    std::string brushes = box(-t, -t, -t, 520 + t, 256 + t, 0) +          // floor under both
                          box(-t, -t, 0, 0, 256 + t, h) + box(520, -t, 0, 520 + t, 256 + t, h) +  // end walls
                          box(0, -t, 0, 520, 0, h) + box(0, 256, 0, 520, 256 + t, h) +              // side walls
                          box(256, 0, 0, 264, 256, h);                                            // the 0.25 m wall
    if (roof) brushes += box(-t, -t, h, 520 + t, 256 + t, h + t);
    return "{\n" + worldspawn + brushes + "}\n" +
           "{\n\"classname\" \"light\"\n\"origin\" \"240 128 64\"\n\"light\" \"300\"\n}\n";
}
}  // namespace

TEST(LightBake, ALampStopsAtAQuarterMetreWall) {
    const map::Level level = compile(twoRooms(true, "\"classname\" \"worldspawn\"\n"));
    const LightBake bake = bakeLevel(level, bakeSkyOf(level), BakeSettings{});
    const Sample lit = sampleFloor(bake, level, 224, 128), beyond = sampleFloor(bake, level, 288, 128);
    const Sample far = sampleFloor(bake, level, 400, 128);
    EXPECT_GT(lit.direct[0], 0.3f) << "the lamp's own room";
    EXPECT_EQ(beyond.direct[0], 0.0f) << "0.5 m past the wall";
    EXPECT_EQ(far.direct[0], 0.0f);
    // A texel past the wall, on the floor and on the side wall that run under it (one face each
    // across both rooms): neither the bilinear read nor the bake's filter carries light over.
    const Sample close = sampleFloor(bake, level, 270, 128);
    EXPECT_EQ(close.direct[0], 0.0f);
    EXPECT_EQ(close.indirect[0], 0.0f);
    const Vec3 onWall = metres(270, 256, 64), wallNormal{0, 0, 1};  // the north wall's inner face, facing -y (OGRE +z)
    const long wall = chartAt(bake, level, onWall, wallNormal);
    ASSERT_GE(wall, 0);
    float d[4], ind[3];
    sampleLightmap(bake, static_cast<std::size_t>(wall), onWall, d, ind);
    EXPECT_EQ(d[0], 0.0f);
    EXPECT_EQ(ind[0], 0.0f);
    // Nor does its bounce cross: the second room is sealed from the first.
    EXPECT_GT(lit.indirect[0], 0.01f);
    EXPECT_EQ(beyond.indirect[0], 0.0f);
}

TEST(LightBake, ASealedRoomUnderSunAndSkyIsDarkAndAnOpenOneIsNot) {
    for (const bool roof : {true, false}) {
        const map::Level level = compile(twoRooms(roof, kSunAndSky));
        const BakeSky sky = bakeSkyOf(level);
        ASSERT_GT(sky.sunColour.x, 0.5);
        ASSERT_GT(sky.above.x, 0.2);
        const LightBake bake = bakeLevel(level, sky, BakeSettings{});
        const Sample s = sampleFloor(bake, level, 400, 128);  // the second room: no lamp
        if (roof) {
            EXPECT_EQ(s.direct[3], 0.0f) << "the sun's visibility under the roof";
            EXPECT_EQ(s.indirect[1], 0.0f) << "no sky is seen, nothing lit bounces";
            Vec3 up, down;
            bake.probes.sample(metres(400, 128, 64), up, down);
            EXPECT_EQ(up.y + down.y, 0.0) << "the irradiance volume in the sealed room";
        } else {
            EXPECT_EQ(s.direct[3], 1.0f) << "the room's middle sees the sun";
            // The sky dome through the opening (a 4 m deep well: about half the dome) plus the bounce.
            EXPECT_GT(s.indirect[1], 0.25f * sky.above.y);
            EXPECT_LT(s.indirect[1], 1.5f * sky.above.y);
            Vec3 up, down;
            bake.probes.sample(metres(400, 128, 64), up, down);
            EXPECT_GT(up.y, 0.2 * sky.above.y);
        }
    }
}

TEST(LightBake, TheSameOnOneThreadAsOnMany) {
    const map::Level level = compile(twoRooms(false, kSunAndSky));
    BakeSettings one, many;
    one.threads = 1;
    many.threads = 3;
    const LightBake a = bakeLevel(level, bakeSkyOf(level), one), b = bakeLevel(level, bakeSkyOf(level), many);
    EXPECT_EQ(a.direct, b.direct);
    EXPECT_EQ(a.indirect, b.indirect);
    EXPECT_EQ(a.probes.up, b.probes.up);
    EXPECT_EQ(a.probes.down, b.probes.down);
}

TEST(LightBake, MoreGatherRaysAgreeWithTheDefault) {
    // The default 36 rays against 400: the indirect light's mean difference over the open rooms'
    // lit texels stays under half an 8-bit step of a mid-grey wall's irradiance (1/255 / 0.3 / 2).
    const map::Level level = compile(twoRooms(false, kSunAndSky));
    BakeSettings fine;
    fine.gatherRays = 400;
    const LightBake a = bakeLevel(level, bakeSkyOf(level), BakeSettings{}), b = bakeLevel(level, bakeSkyOf(level), fine);
    double diff = 0, count = 0;
    for (std::size_t i = 0; i < a.indirect.size(); ++i)
        if (b.indirect[i] > 0) {
            diff += std::abs(a.indirect[i] - b.indirect[i]);
            ++count;
        }
    ASSERT_GT(count, 1000);
    EXPECT_LT(diff / count, 1.0 / 255 / 0.3 / 2);
}
