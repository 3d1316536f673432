// The capsule controller against hand-built geometry: walls, corners, steps, ledges, ramps, falls,
// jumps, crouching, stairs, speeds and garbage input.
#include <gtest/gtest.h>

#include "sim_test_levels.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/rng.h"

using namespace obscura;
using namespace obscura::sim;
using namespace obscura::sim::testlevels;

namespace {
// Pushes on with `c` for `ticks`; returns the largest distance the feet moved in any one tick.
double largestTickMotion(Simulation& s, const PlayerCommand& c, int ticks) {
    double largest = 0;
    for (int i = 0; i < ticks; ++i) {
        const Vec3 before = s.player().feet;
        s.step(c);
        largest = std::max(largest, length(s.player().feet - before));
    }
    return largest;
}

// Ticks until the player stands on the ground (or `limit`).
int ticksToLand(Simulation& s, int limit) {
    int ticks = 0;
    while (!s.player().onGround && ticks < limit) {
        s.step({});
        ++ticks;
    }
    return ticks;
}

map::Level withBrush(const map::LevelBrush& b) {
    map::Level l = floorLevel();
    l.brushes.push_back(b);
    return l;
}
}  // namespace

TEST(Player, StandsOnTheFloorWithoutSinkingOrJittering) {
    Simulation s(floorLevel(), {});
    run(s, {}, 120);
    EXPECT_TRUE(s.player().onGround);
    EXPECT_NEAR(s.player().feet.y, 0.0, 0.01);
    EXPECT_EQ(largestTickMotion(s, {}, 60), 0.0);
}

TEST(Player, WalkingIntoAWallStopsAtTheWall) {
    Simulation s(withBrush(box({-20, 0, -4}, {20, 3, -3})), {});  // wall face at z = -3
    run(s, walk(), 120);
    EXPECT_GT(s.player().feet.z, -3 + kRadius);         // never inside the wall
    EXPECT_LT(s.player().feet.z, -3 + kRadius + 0.02);  // but right against it
    // Keep pushing for a second: no jitter, no creeping, still standing.
    EXPECT_LT(largestTickMotion(s, walk(), 60), 1e-6);
    EXPECT_TRUE(s.player().onGround);
}

TEST(Player, StopsInACornerWithoutJitter) {
    map::Level l = withBrush(box({-20, 0, -4}, {20, 3, -3}));  // wall ahead at z = -3
    l.brushes.push_back(box({2, 0, -20}, {3, 3, 20}));          // wall to the right at x = 2
    l.playerStartYaw = -kPi / 4;                                // facing into the corner
    Simulation s(l, {});
    run(s, walk(), 120);
    EXPECT_GT(s.player().feet.z, -3 + kRadius);
    EXPECT_LT(s.player().feet.x, 2 - kRadius);
    EXPECT_LT(largestTickMotion(s, walk(), 60), 1e-5);  // float noise of two contacts, no more
}

TEST(Player, SlidesAlongAWallHitAtFortyFiveDegrees) {
    map::Level l = withBrush(box({-20, 0, -4}, {20, 3, -3}));
    l.playerStartYaw = -kPi / 4;  // facing 45 degrees right of -Z
    Simulation s(l, {});
    run(s, walk(), 60);
    ASSERT_GT(s.player().feet.z, -3 + kRadius);
    ASSERT_LT(s.player().feet.z, -3 + kRadius + 0.02);  // at the wall
    const double xAtWall = s.player().feet.x;
    double closest = 0;
    for (int i = 0; i < 60; ++i) {
        s.step(walk());
        closest = std::min(closest, s.player().feet.z);
    }
    EXPECT_GT(s.player().feet.x - xAtWall, 2.0);  // a second later it is well along the wall
    EXPECT_GT(closest, -3 + kRadius);
}

TEST(Player, ClimbsAThirtyCentimetreStepButNotASixtyCentimetreLedge) {
    Simulation a(withBrush(box({-5, 0, -20}, {5, 0.3, -2})), {});
    run(a, walk(), 120);
    EXPECT_NEAR(a.player().feet.y, 0.3, 0.01);
    EXPECT_LT(a.player().feet.z, -4.0);
    EXPECT_TRUE(a.player().onGround);

    Simulation b(withBrush(box({-5, 0, -20}, {5, 0.6, -2})), {});
    run(b, walk(), 120);
    EXPECT_NEAR(b.player().feet.y, 0.0, 0.01);
    EXPECT_GT(b.player().feet.z, -2.0 + kRadius);
    EXPECT_LT(largestTickMotion(b, walk(), 30), 1e-6);  // pressing against it does not jitter
}

TEST(Player, ClimbsAFullHeightStepFromStandstillWhileCrouched) {
    // The step height (18 Quake units) with the capsule already touching it: the slowest case.
    const double h = PlayerTuning{}.stepHeight;
    map::Level l = withBrush(box({-5, 0, -20}, {5, h, -2}));
    l.playerStart = {0, 0, -2 + kRadius + 0.01};
    Simulation s(l, {});
    PlayerCommand c = walk();
    c.crouch = true;
    run(s, c, 60);
    EXPECT_NEAR(s.player().feet.y, h, 0.01);
    EXPECT_LT(s.player().feet.z, -2.5);
}

TEST(Player, WalksUpAThirtyDegreeRampButNotASixtyDegreeSlope) {
    const double rise30 = 6 * std::tan(30 * kPi / 180);
    map::Level gentle = withBrush(ramp(-3, 3, -1, 6, rise30));
    gentle.brushes.push_back(box({-3, 0, -27}, {3, rise30, -7}));  // landing at the top
    Simulation a(gentle, {});
    int airborne = 0;
    for (int i = 0; i < 180; ++i) {
        a.step(walk());
        airborne += a.player().onGround ? 0 : 1;
    }
    EXPECT_NEAR(a.player().feet.y, rise30, 0.01);  // on the landing
    EXPECT_LT(a.player().feet.z, -8.0);
    EXPECT_EQ(airborne, 0);  // up the ramp and over its crest without leaving the ground

    const double rise60 = 2 * std::tan(60 * kPi / 180);
    Simulation b(withBrush(ramp(-3, 3, -1, 2, rise60)), {});
    double highest = 0;
    for (int i = 0; i < 180; ++i) {
        b.step(walk());
        highest = std::max(highest, b.player().feet.y);
    }
    EXPECT_LT(highest, 0.5);  // no higher than a step lets it
    EXPECT_GT(b.player().feet.z, -1.0 - 0.5);
}

TEST(Player, SlidesDownASixtyDegreeSlope) {
    const double rise60 = 4 * std::tan(60 * kPi / 180);  // 6.9 m high
    map::Level l = withBrush(ramp(-3, 3, -1, 4, rise60));
    l.playerStart = {0, 0.5 * rise60 + 0.5, -3};  // above the slope's middle
    Simulation s(l, {});
    run(s, {}, 180);
    EXPECT_NEAR(s.player().feet.y, 0.0, 0.01);  // ended on the floor at its foot
    EXPECT_GT(s.player().feet.z, -1.0 - kRadius);
    EXPECT_TRUE(s.player().onGround);
}

TEST(Player, FallsTenMetresAndLandsOnTheFloor) {
    map::Level l = floorLevel();
    l.playerStart = {0, 10, 0};
    Simulation s(l, {});
    const int ticks = ticksToLand(s, 600);
    EXPECT_TRUE(s.player().onGround);
    EXPECT_NEAR(s.player().feet.y, 0.0, 0.01);
    EXPECT_NEAR(ticks, 54, 1);  // sqrt(2 h / g) = sqrt(20 / 25) = 0.894 s = 53.7 ticks
    EXPECT_LT(largestTickMotion(s, {}, 30), 1e-6);
}

TEST(Player, LandsOnAThinSlabEvenAtTerminalVelocity) {
    for (const double height : {10.0, 200.0}) {  // 20 m/s; 50 m/s (0.83 m a tick, 8 slab thicknesses)
        map::Level l;
        l.entities.push_back({});
        l.brushes.push_back(box({-5, -0.1, -5}, {5, 0, 5}));  // a 10 cm slab over nothing
        l.hasPlayerStart = true;
        l.playerStart = {0, height, 0};
        Simulation s(l, {});
        ticksToLand(s, 1200);
        EXPECT_TRUE(s.player().onGround) << "from " << height << " m";
        EXPECT_NEAR(s.player().feet.y, 0.0, 0.01) << "from " << height << " m";
        run(s, {}, 30);
        EXPECT_NEAR(s.player().feet.y, 0.0, 0.01) << "from " << height << " m";
    }
}

TEST(Player, JumpReachesQuakesApex) {
    Simulation s(floorLevel(), {});
    run(s, {}, 10);
    const double floorY = s.player().feet.y;
    PlayerCommand j;
    j.jump = true;
    s.step(j);
    EXPECT_FALSE(s.player().onGround);
    double apex = 0;
    int airTicks = 1;
    for (int i = 0; i < 120 && !s.player().onGround; ++i, ++airTicks) {
        s.step({});
        apex = std::max(apex, s.player().feet.y - floorY);
    }
    // Quake's 270 u/s against 800 u/s^2: 270^2 / 1600 = 45.6 units = 1.424 m.
    EXPECT_NEAR(apex * 32, 45.6, 0.5);
    EXPECT_NEAR(airTicks, 41, 2);  // 2 v / g = 2 * 8.4375 / 25 = 0.675 s
    EXPECT_TRUE(s.player().onGround);
    // Holding jump in the air does nothing: no double jump.
    run(s, {}, 5);
    s.step(j);
    run(s, j, 10);
    EXPECT_LT(s.player().feet.y - floorY, 1.5);
}

TEST(Player, JumpsOntoACrateHighLedge) {
    // A 0.75 m ledge: too high to step, low enough to jump onto.
    Simulation s(withBrush(box({-5, 0, -20}, {5, 0.75, -2})), {});
    run(s, walk(), 40);
    ASSERT_NEAR(s.player().feet.y, 0.0, 0.01);
    PlayerCommand c = walk();
    c.jump = true;
    s.step(c);
    run(s, walk(), 60);
    EXPECT_NEAR(s.player().feet.y, 0.75, 0.01);
}

TEST(Player, CrouchesUnderALowCeilingAndCannotStandThere) {
    map::Level l = withBrush(box({-5, 1.4, -20}, {5, 1.6, -2}));  // a 1.4 m high opening from z = -2
    Simulation s(l, {});
    run(s, walk(), 60);
    EXPECT_GT(s.player().feet.z, -2 + kRadius - 0.01);  // standing, the head stops at the lintel
    PlayerCommand c = walk();
    c.crouch = true;
    run(s, c, 90);
    EXPECT_LT(s.player().feet.z, -4);  // went under crouched
    EXPECT_TRUE(s.player().crouching);
    EXPECT_NEAR(s.player().height, 1.1, 1e-6);
    run(s, {}, 10);  // let go of crouch under the ceiling: stays crouched
    EXPECT_TRUE(s.player().crouching);
    EXPECT_LT(s.player().eye().y, 1.4);
    run(s, walk(-1), 150);  // back out, crouch still not held
    EXPECT_GT(s.player().feet.z, -2 + kRadius);
    EXPECT_FALSE(s.player().crouching);  // stood up as soon as the head had room
    EXPECT_NEAR(s.player().eye().y, 1.65, 0.01);
}

TEST(Player, WalksDownStairsStayingOnTheGround) {
    map::Level l = floorLevel();
    for (int i = 0; i < 8; ++i)  // 0.25 m steps, 0.35 m deep, descending towards -Z from 2 m
        l.brushes.push_back(box({-3, 0, -2.0 - 0.35 * (i + 1)}, {3, 2.0 - 0.25 * i, -2.0 - 0.35 * i}));
    l.brushes.push_back(box({-3, 0, 3}, {3, 2.0, -2.0}));  // start platform
    l.playerStart = {0, 2.0, 0};
    Simulation s(l, {});
    int airborne = 0;
    double lowest = 2.0, biggestDrop = 0;
    for (int i = 0; i < 150; ++i) {
        s.step(walk());
        airborne += s.player().onGround ? 0 : 1;
        biggestDrop = std::max(biggestDrop, lowest - s.player().feet.y);
        lowest = std::min(lowest, s.player().feet.y);
    }
    EXPECT_NEAR(s.player().feet.y, 0.0, 0.01);
    EXPECT_EQ(airborne, 0);          // it follows the steps down, never falls
    EXPECT_LE(biggestDrop, 0.25 + 0.01);  // at most one step a tick
}

namespace {
// Quake units (32 a metre, engine_ext/map/level.h).
constexpr double kUnit = 1.0 / 32;

// `count` steps of `riser` x `tread` units rising towards -Z from z = -2, 6 m wide, and a 30 m
// landing at the top; the player at the origin facing them.
map::Level stairs(int count, double riser, double tread) {
    map::Level l = floorLevel();
    for (int i = 0; i < count; ++i)
        l.brushes.push_back(box({-3, 0, -2.0 - tread * kUnit * (i + 1)}, {3, riser * kUnit * (i + 1), -2.0 - tread * kUnit * i}));
    const double top = count * riser * kUnit, end = -2.0 - count * tread * kUnit;
    l.brushes.push_back(box({-3, 0, end - 30}, {3, top, end}));
    return l;
}
}  // namespace

TEST(Player, WalksUpQuakeStairsWithoutJumping) {
    // Quake's standard stair: 16-unit (0.5 m) risers; treads from 16 units (narrower than the
    // capsule: it stands on step edges) to 32. Walking only, never leaving the ground.
    for (const double tread : {16.0, 24.0, 32.0}) {
        Simulation s(stairs(8, 16, tread), {});
        int airborne = 0;
        for (int i = 0; i < 180; ++i) {
            s.step(walk());
            airborne += s.player().onGround ? 0 : 1;
        }
        EXPECT_NEAR(s.player().feet.y, 8 * 16 * kUnit, 0.01) << tread << "-unit treads";
        EXPECT_LT(s.player().feet.z, -2.0 - 8 * tread * kUnit) << tread << "-unit treads";  // on the landing
        EXPECT_EQ(airborne, 0) << tread << "-unit treads";
    }
}

TEST(Player, StepsUpEighteenQuakeUnitsButNotNineteen) {
    // Quake's STEPSIZE is 18 units: one 18-unit step climbs, one 19-unit step stops the player.
    Simulation a(stairs(1, 18, 64), {});
    run(a, walk(), 120);
    EXPECT_NEAR(a.player().feet.y, 18 * kUnit, 0.01);
    EXPECT_LT(a.player().feet.z, -4.0);

    Simulation b(stairs(1, 19, 64), {});
    run(b, walk(), 120);
    EXPECT_NEAR(b.player().feet.y, 0.0, 0.01);
    EXPECT_GT(b.player().feet.z, -2.0 + kRadius - 0.01);
    EXPECT_LT(largestTickMotion(b, walk(), 30), 1e-6);  // pressing against it does not jitter
}

TEST(Player, JumpsOntoAFortyUnitLedge) {
    // Quake's 45.6-unit jump apex gets onto a 40-unit (1.25 m) ledge from a walk.
    Simulation s(stairs(1, 40, 64), {});
    run(s, walk(), 40);
    ASSERT_NEAR(s.player().feet.y, 0.0, 0.01);
    PlayerCommand c = walk();
    c.jump = true;
    s.step(c);
    run(s, walk(), 60);
    EXPECT_NEAR(s.player().feet.y, 40 * kUnit, 0.01);
}

TEST(Player, WalksOffALedgeAndFalls) {
    map::Level l = floorLevel();
    l.brushes.push_back(box({-3, 0, 3}, {3, 2.0, -2.0}));  // a 2 m platform ending at z = -2
    l.playerStart = {0, 2.0, 0};
    Simulation s(l, {});
    bool fell = false;
    for (int i = 0; i < 120; ++i) {
        s.step(walk());
        fell |= !s.player().onGround && s.player().velocity.y < -3;
    }
    EXPECT_TRUE(fell);
    EXPECT_NEAR(s.player().feet.y, 0.0, 0.01);
    EXPECT_TRUE(s.player().onGround);
}

TEST(Player, SprintIsFasterAndCrouchIsSlower) {
    auto distance = [](bool sprint, bool crouch) {
        Simulation s(floorLevel(), {});
        PlayerCommand c = walk();
        c.sprint = sprint;
        c.crouch = crouch;
        run(s, c, 30);  // up to speed
        const Vec3 a = s.player().feet;
        run(s, c, 60);
        return length(s.player().feet - a);
    };
    const double walking = distance(false, false), sprinting = distance(true, false), crouching = distance(false, true);
    // Quake's 200 u/s walk and 320 u/s run (+speed), one second of each; crouched 2.5 m/s.
    EXPECT_NEAR(walking * 32, 200, 2);
    EXPECT_NEAR(sprinting * 32, 320, 3);
    EXPECT_NEAR(crouching, 2.5, 0.03);
}

TEST(Player, StopsQuicklyOnLettingGo) {
    Simulation s(floorLevel(), {});
    run(s, walk(), 60);
    int ticks = 0;
    while (length(s.player().velocity) > 0 && ticks < 60) {
        s.step({});
        ++ticks;
    }
    // Friction 6 from the 6.25 m/s walk: e^-6t down to the 2 m/s stop speed (0.19 s), then 12 m/s^2
    // (0.17 s): about a third of a second.
    EXPECT_LE(ticks, 24);
    EXPECT_GT(ticks, 5);   // but not a dead stop
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

TEST(Player, GarbageCommandsAreHarmless) {
    Simulation s(floorLevel(), {});
    PlayerCommand c;
    c.forward = std::numeric_limits<float>::quiet_NaN();
    c.right = 1e30f;  // clamped to full right
    c.yawDelta = std::numeric_limits<float>::infinity();
    c.pitchDelta = std::numeric_limits<float>::quiet_NaN();
    run(s, c, 60);
    const PlayerState& p = s.player();
    for (double v : {p.feet.x, p.feet.y, p.feet.z, p.velocity.x, static_cast<double>(p.yaw), static_cast<double>(p.pitch)})
        EXPECT_TRUE(std::isfinite(v));
    EXPECT_NEAR(p.feet.x, 5.6, 0.6);  // walked right at walking speed (6.25 m/s, accelerating)
    EXPECT_TRUE(p.onGround);
}

TEST(Player, RoamingAClutteredRoomNeverEndsInsideGeometry) {
    // 400 random boxes and ramps in a walled 40 x 40 m room plus falling crates; random commands
    // (walk, strafe, jump, crouch, sprint, turn) held for a third of a second each.
    map::Level l = floorLevel();
    for (double x : {-20.0, 20.0}) l.brushes.push_back(box({x - 1, 0, -20}, {x, 6, 20}));
    for (double z : {-20.0, 20.0}) l.brushes.push_back(box({-20, 0, z - 1}, {20, 6, z}));
    Rng r(1);
    while (l.brushes.size() < 400) {
        const double x = r.uniform(-19, 19), z = r.uniform(-19, 19), w = r.uniform(0.2f, 1.5f), d = r.uniform(0.2f, 1.5f);
        if (r.below(4) == 0) l.brushes.push_back(ramp(x, x + w, z, 2 * d, r.uniform(0.2f, 2.5f)));
        else l.brushes.push_back(box({x, 0, z}, {x + w, r.uniform(0.1f, 3), z + d}));
    }
    for (int i = 0; i < 10; ++i) l.entities.push_back(crate({r.uniform(-15, 15), 4, r.uniform(-15, 15)}));
    l.playerStart = {0, 5, 0};
    for (std::uint64_t seed : {1, 2, 3}) {
        Simulation s(l, {});
        Rng input(seed);
        const btCapsuleShape stand(0.35f, 1.1f), crouch(0.35f, 0.4f);
        PlayerCommand c;
        double deepest = 0, farthest = 0;
        for (int t = 0; t < 6000; ++t) {
            if (t % 20 == 0) {
                c = PlayerCommand{};
                c.forward = input.uniform(-1, 1);
                c.right = input.uniform(-1, 1);
                c.jump = input.below(5) == 0;
                c.crouch = input.below(6) == 0;
                c.sprint = input.below(2) == 0;
                c.yawDelta = input.uniform(-0.1f, 0.1f);
            }
            s.step(c);
            const PlayerState& p = s.player();
            const Vec3 centre = p.feet + Vec3{0, p.height / 2.0, 0};
            for (const auto& k : s.physics().contacts(p.crouching ? crouch : stand, centre, 0.0))
                deepest = std::min(deepest, k.distance);
            farthest = std::max({farthest, std::abs(p.feet.x), std::abs(p.feet.z)});
            ASSERT_GT(p.feet.y, -0.05) << "through the floor at tick " << t << ", seed " << seed;
        }
        // Millimetres at most (wedged between two steep faces), resolved the next tick.
        EXPECT_GT(deepest, -0.01) << "seed " << seed;
        EXPECT_LT(farthest, 20 - kRadius) << "seed " << seed;  // never through the outer walls
    }
}
