#include <gtest/gtest.h>

#include "sim/simulation.h"
#include "sim_test_levels.h"

using namespace obscura;
using namespace obscura::sim;
using namespace obscura::sim::testlevels;

namespace {
map::Level levelWithCrates() {
    map::Level l = floorLevel();
    for (int i = 0; i < 3; ++i) {
        map::LevelEntity e;
        e.classname = "prop_crate";
        e.hasOrigin = true;
        e.origin = {-1.0 + i, 2.0 + i, -3};  // dropped from above the floor
        l.entities.push_back(e);
    }
    return l;
}

PlayerCommand scripted(int tick) {
    PlayerCommand c;
    c.forward = tick % 90 < 60 ? 1.0f : 0.0f;
    c.right = tick % 50 < 20 ? -1.0f : 0.0f;
    c.jump = tick % 70 == 5;
    c.yawDelta = tick % 30 < 10 ? 0.01f : -0.004f;
    return c;
}
}  // namespace

TEST(Simulation, SameCommandsGiveTheSameHashEveryTick) {
    Simulation a(levelWithCrates(), {}), b(levelWithCrates(), {});
    for (int t = 0; t < 400; ++t) {
        a.step(scripted(t));
        b.step(scripted(t));
        ASSERT_EQ(a.stateHash(), b.stateHash()) << "diverged at tick " << t;
    }
}

TEST(Simulation, DifferentInputOrSeedChangesTheHash) {
    Simulation a(levelWithCrates(), {}), b(levelWithCrates(), {});
    for (int t = 0; t < 100; ++t) {
        a.step(scripted(t));
        PlayerCommand c = scripted(t);
        if (t == 50) c.yawDelta += 1e-4f;
        b.step(c);
    }
    EXPECT_NE(a.stateHash(), b.stateHash());
    SimConfig other;
    other.seed = 2;
    EXPECT_NE(Simulation(floorLevel(), {}).stateHash(), Simulation(floorLevel(), other).stateHash());
}

TEST(Simulation, CratesFallAndComeToRest) {
    Simulation s(levelWithCrates(), {});
    for (int t = 0; t < 300; ++t) s.step({});
    const auto poses = s.bodyPoses();
    ASSERT_EQ(poses.size(), 3u);
    for (const auto& p : poses) {
        EXPECT_NEAR(p.position.y, 0.375, 0.02);  // resting on the floor
        EXPECT_NEAR(p.halfExtents.x, 0.375, 1e-9);
    }
    EXPECT_NEAR(s.physics().dynamicBody(0).getLinearVelocity().length(), 0.0, 1e-2);
}

TEST(Simulation, PlayerPushesACrate) {
    map::Level l = floorLevel();
    map::LevelEntity e;
    e.classname = "prop_crate";
    e.hasOrigin = true;
    e.origin = {0, 0, -2};
    l.entities.push_back(e);
    Simulation s(l, {});
    PlayerCommand c;
    c.forward = 1;
    for (int t = 0; t < 120; ++t) s.step(c);
    EXPECT_LT(s.bodyPoses()[0].position.z, -2.5);
}

TEST(Simulation, RayCastHitsStaticAndDynamic) {
    Simulation s(levelWithCrates(), {});
    for (int t = 0; t < 200; ++t) s.step({});
    const auto floor = s.physics().rayCast({5, 5, 5}, {5, -5, 5});
    ASSERT_TRUE(floor);
    EXPECT_NEAR(floor->point.y, 0.0, 2e-3);  // within the 1 mm hull margin
    EXPECT_NEAR(floor->normal.y, 1.0, 1e-3);
    EXPECT_EQ(floor->dynamicBody, -1);
    const auto crate = s.physics().rayCast({-1, 5, -3}, {-1, -5, -3});
    ASSERT_TRUE(crate);
    EXPECT_EQ(crate->dynamicBody, 0);
    EXPECT_NEAR(crate->point.y, 0.75, 0.02);
    EXPECT_FALSE(s.physics().rayCast({0, 5, 0}, {0, 50, 0}));
}
