// The whole simulation: fixed-step determinism and its hash, the start pose, crates and the player.
#include <gtest/gtest.h>

#include "sim_test_levels.h"

#include <set>

using namespace obscura;
using namespace obscura::sim;
using namespace obscura::sim::testlevels;

namespace {
map::Level levelWithCrates() {
    map::Level l = floorLevel();
    for (int i = 0; i < 3; ++i) l.entities.push_back(crate({-1.0 + 1.2 * i, 2.0 + i, -3}));  // dropped from above
    l.brushes.push_back(box({-3, 0, -8}, {3, 0.3, -6}));  // a step to climb
    return l;
}

// Walks, strafes, jumps, crouches and turns: exercises every path of the controller.
PlayerCommand scripted(int tick) {
    PlayerCommand c;
    c.forward = tick % 90 < 60 ? 1.0f : -0.5f;
    c.right = tick % 50 < 20 ? -1.0f : 0.0f;
    c.jump = tick % 70 == 5;
    c.crouch = tick % 130 > 100;
    c.sprint = tick % 200 < 50;
    c.yawDelta = tick % 30 < 10 ? 0.02f : -0.008f;
    c.pitchDelta = tick % 40 < 20 ? 0.01f : -0.01f;
    return c;
}
}  // namespace

TEST(Simulation, SameCommandsGiveTheSameHashEveryTick) {
    Simulation a(levelWithCrates(), {}), b(levelWithCrates(), {});
    ASSERT_EQ(a.stateHash(), b.stateHash());
    std::set<std::uint64_t> seen;
    for (int t = 0; t < 600; ++t) {
        a.step(scripted(t));
        b.step(scripted(t));
        ASSERT_EQ(a.stateHash(), b.stateHash()) << "diverged at tick " << t;
        seen.insert(a.stateHash());
    }
    EXPECT_EQ(a.tick(), 600u);
    EXPECT_EQ(seen.size(), 600u);  // the tick alone makes every hash different
    EXPECT_EQ(a.stateHashHex().size(), 16u);
    EXPECT_EQ(a.stateHashHex(), b.stateHashHex());
}

TEST(Simulation, DifferentInputOrSeedChangesTheHash) {
    Simulation a(levelWithCrates(), {}), b(levelWithCrates(), {});
    for (int t = 0; t < 100; ++t) {
        a.step(scripted(t));
        PlayerCommand c = scripted(t);
        if (t == 50) c.yawDelta += 1e-4f;  // one tiny mouse difference
        b.step(c);
    }
    EXPECT_NE(a.stateHash(), b.stateHash());
    EXPECT_GT(length(a.player().feet - b.player().feet), 0.0);

    SimConfig other;
    other.seed = 2;
    Simulation c(floorLevel(), {}), d(floorLevel(), other);
    EXPECT_NE(c.stateHash(), d.stateHash());
    // The RNG is part of the state: drawing a number changes the hash.
    Simulation e(floorLevel(), {});
    const auto before = e.stateHash();
    e.rng().nextU32();
    EXPECT_NE(e.stateHash(), before);
}

TEST(Simulation, HashFollowsTheCrates) {
    map::Level l = floorLevel();
    l.entities.push_back(crate({2, 1.0, 0}));
    Simulation a(l, {});
    l.entities.back().origin.y = 1.01;  // the same crate dropped 1 cm higher
    Simulation b(l, {});
    for (int t = 0; t < 10; ++t) {
        a.step({});
        b.step({});
    }
    EXPECT_EQ(a.player().feet, b.player().feet);
    EXPECT_NE(a.stateHash(), b.stateHash());
}

TEST(Simulation, StartsAtThePlayerStartOrTheOrigin) {
    map::Level l = floorLevel();
    l.playerStart = {1, 0, 2};
    l.playerStartYaw = 0.5;
    Simulation a(l, {});
    EXPECT_EQ(a.player().feet, Vec3(1, 0, 2));
    EXPECT_NEAR(a.player().yaw, 0.5, 1e-7);
    EXPECT_NEAR(a.player().eye().y, 1.65, 1e-6);
    EXPECT_FALSE(a.player().crouching);

    l.hasPlayerStart = false;
    Simulation b(l, {});
    EXPECT_EQ(b.player().feet, Vec3(0, 0, 0));
    EXPECT_EQ(b.player().yaw, 0.0f);

    SimConfig start;
    start.overrideStart = true;
    start.startFeet = {3, 0, 3};
    start.startYaw = 1;
    start.startPitch = 0.25;
    Simulation c(l, start);
    EXPECT_EQ(c.player().feet, Vec3(3, 0, 3));
    EXPECT_NEAR(c.player().pitch, 0.25, 1e-7);
}

TEST(Simulation, TickRateSetsTheStepAndBadRatesThrow) {
    SimConfig fast;
    fast.tickRate = 120;
    Simulation s(floorLevel(), fast);
    EXPECT_DOUBLE_EQ(s.dt(), 1.0 / 120);
    run(s, walk(), 240);  // two seconds at 120 Hz: same walking speed
    // Two seconds at the walking speed, less about 0.4 m getting up to it.
    EXPECT_NEAR(s.player().feet.z, -(2 * PlayerTuning{}.walkSpeed - 0.4), 0.2);
    SimConfig bad;
    bad.tickRate = 0;
    EXPECT_THROW(Simulation(floorLevel(), bad), SimError);
    bad.tickRate = std::nan("");
    EXPECT_THROW(Simulation(floorLevel(), bad), SimError);
}

TEST(Simulation, PlayerPushesACrate) {
    map::Level l = floorLevel();
    l.entities.push_back(crate({0, 0, -2}));
    Simulation s(l, {});
    run(s, walk(), 120);
    const auto pose = s.bodyPoses()[0];
    EXPECT_LT(pose.position.z, -3.0);            // shoved along
    EXPECT_NEAR(pose.position.x, 0.0, 0.1);     // straight ahead
    EXPECT_NEAR(pose.position.y, 0.375, 0.02);  // still on the floor
    EXPECT_GT(s.player().feet.z, pose.position.z + 0.375 + kRadius - 0.01);  // never inside it
}

TEST(Simulation, PlayerStandsOnACrateAndDoesNotPushIt) {
    map::Level l = floorLevel();
    l.entities.push_back(crate({0, 0, 0}));
    l.playerStart = {0, 2, 0};
    Simulation s(l, {});
    run(s, {}, 120);
    EXPECT_TRUE(s.player().onGround);
    EXPECT_NEAR(s.player().feet.y, 0.75, 0.02);
    EXPECT_NEAR(s.bodyPoses()[0].position.x, 0.0, 1e-3);
    EXPECT_NEAR(s.bodyPoses()[0].position.z, 0.0, 1e-3);
}

TEST(Simulation, RayCastFindsTheCrateAfterItSettles) {
    Simulation s(levelWithCrates(), {});
    run(s, {}, 200);
    const auto crateHit = s.physics().rayCast({-1, 5, -3}, {-1, -5, -3});
    ASSERT_TRUE(crateHit);
    EXPECT_EQ(crateHit->dynamicBody, 0);
    EXPECT_NEAR(crateHit->point.y, 0.75, 0.01);
    const auto second = s.physics().rayCast({0.2, 5, -3}, {0.2, -5, -3});
    ASSERT_TRUE(second);
    EXPECT_EQ(second->dynamicBody, 1);
    const auto floor = s.physics().rayCast({5, 5, 5}, {5, -5, 5});
    ASSERT_TRUE(floor);
    EXPECT_EQ(floor->dynamicBody, -1);
}
