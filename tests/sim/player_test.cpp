#include <gtest/gtest.h>

#include "sim/simulation.h"
#include "sim_test_levels.h"

#include <cmath>

using namespace obscura;
using namespace obscura::sim;
using namespace obscura::sim::testlevels;

namespace {
constexpr double kPi = 3.14159265358979323846;

PlayerCommand walk(float forward = 1, float right = 0) {
    PlayerCommand c;
    c.forward = forward;
    c.right = right;
    return c;
}

void run(Simulation& s, const PlayerCommand& c, int ticks) {
    for (int i = 0; i < ticks; ++i) s.step(c);
}
}  // namespace

TEST(Player, StandsOnTheFloorWithoutSinkingOrJittering) {
    Simulation s(floorLevel(), {});
    run(s, {}, 120);
    EXPECT_TRUE(s.player().onGround);
    EXPECT_NEAR(s.player().feet.y, 0.0, 0.01);
    const Vec3 before = s.player().feet;
    run(s, {}, 60);
    EXPECT_LT(length(s.player().feet - before), 1e-6);
}

TEST(Player, WalkingIntoAWallStopsAtTheWall) {
    map::Level l = floorLevel();
    l.brushes.push_back(box({-20, 0, -4}, {20, 3, -3}));  // wall face at z = -3
    Simulation s(l, {});
    run(s, walk(), 120);
    const double radius = 0.35;
    EXPECT_GT(s.player().feet.z, -3 + radius - 0.01);  // never inside the wall
    EXPECT_LT(s.player().feet.z, -3 + radius + 0.05);  // but right against it
    const Vec3 before = s.player().feet;
    run(s, walk(), 60);  // keep pushing: no jitter, no creeping
    EXPECT_LT(length(s.player().feet - before), 1e-3);
}

TEST(Player, SlidesAlongAWallHitAtAnAngle) {
    map::Level l = floorLevel();
    l.brushes.push_back(box({-20, 0, -4}, {20, 3, -3}));
    l.playerStartYaw = -kPi / 4;  // facing 45 degrees right of -Z
    Simulation s(l, {});
    run(s, walk(), 60);
    const double xAtWall = s.player().feet.x;
    run(s, walk(), 60);
    EXPECT_GT(s.player().feet.x - xAtWall, 1.0);  // keeps moving along the wall
    EXPECT_GT(s.player().feet.z, -3 + 0.34);
}

TEST(Player, ClimbsAStepButNotALedge) {
    map::Level step = floorLevel();
    step.brushes.push_back(box({-5, 0, -20}, {5, 0.3, -2}));
    Simulation a(step, {});
    run(a, walk(), 120);
    EXPECT_NEAR(a.player().feet.y, 0.3, 0.02);
    EXPECT_LT(a.player().feet.z, -3.0);

    map::Level ledge = floorLevel();
    ledge.brushes.push_back(box({-5, 0, -20}, {5, 0.6, -2}));
    Simulation b(ledge, {});
    run(b, walk(), 120);
    EXPECT_NEAR(b.player().feet.y, 0.0, 0.02);
    EXPECT_GT(b.player().feet.z, -2.0 + 0.34);
}

TEST(Player, WalksUpAThirtyDegreeRampButNotASixtyDegreeSlope) {
    map::Level gentle = floorLevel();
    gentle.brushes.push_back(ramp(-3, 3, -1, 6, 6 * std::tan(30 * kPi / 180)));
    gentle.brushes.push_back(box({-3, 0, -17}, {3, 6 * std::tan(30 * kPi / 180), -7}));  // landing
    Simulation a(gentle, {});
    run(a, walk(), 180);
    EXPECT_GT(a.player().feet.y, 3.0);

    map::Level steep = floorLevel();
    steep.brushes.push_back(ramp(-3, 3, -1, 2, 2 * std::tan(60 * kPi / 180)));
    Simulation b(steep, {});
    run(b, walk(), 180);
    EXPECT_LT(b.player().feet.y, 0.5);
}

TEST(Player, WalksDownStairsStayingOnTheGround) {
    map::Level l = floorLevel();
    for (int i = 0; i < 8; ++i)  // descending towards -Z: top step at 2 m
        l.brushes.push_back(box({-3, 0, -2.0 - 0.35 * (i + 1)}, {3, 2.0 - 0.25 * i, -2.0 - 0.35 * i}));
    l.brushes.push_back(box({-3, 0, 3}, {3, 2.0, -2.0}));  // start platform
    l.playerStart = {0, 2.0, 0};
    Simulation s(l, {});
    int longestAirborne = 0, airborne = 0;
    double fastestFall = 0;
    for (int i = 0; i < 150; ++i) {
        s.step(walk());
        airborne = s.player().onGround ? 0 : airborne + 1;
        longestAirborne = std::max(longestAirborne, airborne);
        fastestFall = std::max(fastestFall, -s.player().velocity.y);
    }
    EXPECT_LT(s.player().feet.y, 0.3);
    EXPECT_LE(longestAirborne, 2);  // at most a tick or two grazing a step's edge
    EXPECT_LT(fastestFall, 0.5);    // never drops off a step into a fall
}

TEST(Player, FallsAndLandsEvenOnAThinSlab) {
    map::Level l;
    l.entities.push_back({});
    l.brushes.push_back(box({-5, -0.1, -5}, {5, 0, 5}));  // a 10 cm slab
    l.hasPlayerStart = true;
    l.playerStart = {0, 10, 0};
    Simulation s(l, {});
    int ticks = 0;
    while (!s.player().onGround && ticks < 600) {
        s.step({});
        ++ticks;
    }
    EXPECT_TRUE(s.player().onGround);
    EXPECT_NEAR(s.player().feet.y, 0.0, 0.02);
    // sqrt(2 h / g) = sqrt(20 / 20) = 1 s = 60 ticks
    EXPECT_NEAR(ticks, 60, 3);
    run(s, {}, 30);
    EXPECT_NEAR(s.player().feet.y, 0.0, 0.02);
}

TEST(Player, JumpReachesAboutAMetre) {
    Simulation s(floorLevel(), {});
    run(s, {}, 10);
    PlayerCommand j;
    j.jump = true;
    s.step(j);
    double apex = 0;
    for (int i = 0; i < 120; ++i) {
        s.step({});
        apex = std::max(apex, s.player().feet.y);
    }
    EXPECT_NEAR(apex, 1.0, 0.06);
    EXPECT_TRUE(s.player().onGround);
}

TEST(Player, CrouchesUnderALowCeilingAndStaysCrouched) {
    map::Level l = floorLevel();
    l.brushes.push_back(box({-5, 1.4, -20}, {5, 1.6, -2}));  // a 1.4 m high opening
    Simulation s(l, {});
    PlayerCommand c = walk();
    c.crouch = true;
    run(s, c, 90);
    EXPECT_LT(s.player().feet.z, -3);  // went under
    EXPECT_TRUE(s.player().crouching);
    run(s, {}, 10);  // let go of crouch under the ceiling
    EXPECT_TRUE(s.player().crouching);
    EXPECT_LT(s.player().eye().y, 1.4);
    // Walking without crouch held is impossible to stand in; back out and stand.
    run(s, walk(-1), 120);
    run(s, {}, 5);
    EXPECT_FALSE(s.player().crouching);
}

TEST(Player, MouseLookTurnsAndPitchIsClamped) {
    Simulation s(floorLevel(), {});
    PlayerCommand c;
    c.yawDelta = static_cast<float>(kPi / 2);
    c.pitchDelta = 3.0f;
    s.step(c);
    EXPECT_NEAR(s.player().yaw, kPi / 2, 1e-6);
    EXPECT_NEAR(s.player().pitch, 89 * kPi / 180, 1e-6);
    run(s, walk(), 30);  // yaw +90 degrees faces -X
    EXPECT_LT(s.player().feet.x, -1.0);
    EXPECT_NEAR(s.player().feet.z, 0.0, 1e-6);
}
