// Real maps through the real compiler and simulation: the player stands, walks and stays inside.
#include <gtest/gtest.h>

#include "map/map_compile.h"
#include "sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

using namespace obscura;

namespace {
// Walks forward, turning 60 degrees every second; returns the distance covered on the ground.
double walk(const map::Level& level, int ticks, sim::Simulation& s) {
    double travelled = 0;
    Vec3 last = s.player().feet;
    for (int t = 0; t < ticks; ++t) {
        sim::PlayerCommand c;
        c.forward = 1;
        if (t % 60 == 59) c.yawDelta = static_cast<float>(3.14159265358979 / 3);
        s.step(c);
        const Vec3 p = s.player().feet;
        travelled += std::hypot(p.x - last.x, p.z - last.z);
        last = p;
        EXPECT_GT(p.y, level.bounds.min.y - 1.0) << "fell out of the level at tick " << t;
    }
    return travelled;
}
}  // namespace

TEST(Simulation, WalksTheDefaultArena) {
    const auto path = std::filesystem::path(OBSCURA_SOURCE_DIR) / "media/levels/arena.map";
    const map::Level level = map::loadLevel(path.string());
    sim::Simulation s(level, {});
    for (int t = 0; t < 30; ++t) s.step({});
    EXPECT_TRUE(s.player().onGround);
    EXPECT_GT(walk(level, 600, s), 10.0);
}

TEST(Simulation, WalksLibreQuakeE3m4) {
    const auto path = std::filesystem::path(OBSCURA_THIRD_PARTY_DIR) / "librequake/e3m4.map";
    const map::Level level = map::loadLevel(path.string());
    sim::Simulation s(level, {});
    for (int t = 0; t < 60; ++t) s.step({});
    EXPECT_TRUE(s.player().onGround) << "the player start should stand on the floor";
    EXPECT_GT(walk(level, 600, s), 8.0);
}

TEST(Simulation, WalksUpTheStairsLevelWithoutJumping) {
    // tests/sim/levels/stairs.map: twelve 16-unit risers to a landing 192 units (6 m) up.
    const auto path = std::filesystem::path(OBSCURA_SOURCE_DIR) / "tests/sim/levels/stairs.map";
    const map::Level level = map::loadLevel(path.string());
    sim::Simulation s(level, {});
    int airborne = 0;
    double highest = 0;
    sim::PlayerCommand c;
    c.forward = 1;
    for (int t = 0; t < 150; ++t) {
        s.step(c);
        airborne += s.player().onGround ? 0 : 1;
        highest = std::max(highest, s.player().feet.y);
    }
    EXPECT_NEAR(s.player().feet.y, 192.0 / 32, 0.02);  // on the landing
    EXPECT_LT(highest, 192.0 / 32 + 0.02);              // climbed, never hopped
    EXPECT_EQ(airborne, 0);
}
