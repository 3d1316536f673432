// Combat in the simulation: hitscan hits and damage, walls in the way, spread from the seed, fire
// rate, magazine and reload, recoil, props knocked by shots, targets rising and moving, grenades
// (charge, bounce, walls, fuse), movement cues, and tick-by-tick determinism.
#include <gtest/gtest.h>

#include "sim/simulation.h"
#include "sim_test_levels.h"

#include <cmath>
#include <vector>

using namespace obscura;
using namespace obscura::sim;
using namespace obscura::sim::testlevels;

namespace {
map::LevelEntity pointEntity(const char* cls, const Vec3& origin, double yaw = 0,
                             std::vector<std::pair<std::string, std::string>> keys = {}) {
    map::LevelEntity e;
    e.classname = cls;
    e.hasOrigin = true;
    e.origin = origin;
    e.yaw = yaw;
    e.keys = std::move(keys);
    return e;
}

// The player at the origin faces -Z (yaw 0); a pop-up target 10 m ahead faces back at it (yaw pi).
map::Level rangeLevel() {
    map::Level l = floorLevel();
    l.entities.push_back(pointEntity("target_popup", {0, 0, -10}, kPi));
    return l;
}

PlayerCommand fire() {
    PlayerCommand c;
    c.fire = true;
    return c;
}

int count(const std::vector<SimEvent>& events, SimEventType type) {
    int n = 0;
    for (const auto& e : events) n += e.type == type;
    return n;
}

// Taps the trigger once every `gap` ticks (a fresh press each time), `shots` times.
std::vector<SimEvent> tapShots(Simulation& sim, int shots, int gap = 8) {
    std::vector<SimEvent> all;
    for (int s = 0; s < shots; ++s)
        for (int t = 0; t < gap; ++t) {
            sim.step(t == 0 ? fire() : PlayerCommand{});
            all.insert(all.end(), sim.events().begin(), sim.events().end());
        }
    return all;
}

SimConfig aimedAt(double pitchDegrees = 0) {
    SimConfig c;
    c.overrideStart = true;
    c.startFeet = {0, 0, 0};
    c.startPitch = pitchDegrees * kPi / 180;
    return c;
}
}  // namespace

TEST(CombatHits, ThreeHitsDropATargetScoreAndItRisesAgain) {
    auto level = rangeLevel();
    // The board's top half at eye height: aim a little down at it (eye 1.65 m, board 1.0-1.6 m).
    Simulation sim(level, aimedAt(-1.5));
    const auto events = tapShots(sim, 3, 20);  // slow taps: recoil recovers, spread stays tight
    EXPECT_EQ(count(events, SimEventType::Shot), 3);
    EXPECT_EQ(count(events, SimEventType::TargetHit), 3);
    EXPECT_EQ(count(events, SimEventType::TargetDown), 1);
    EXPECT_EQ(sim.score(), 3 * 10 + 50);
    EXPECT_FALSE(sim.targets()[0].up);
    EXPECT_EQ(sim.weapon().magazine, 27);
    // Impacts carry the hit point and the board's normal (facing the shooter: +Z) for decals.
    for (const auto& e : events)
        if (e.type == SimEventType::Impact) {
            EXPECT_EQ(e.surface, Surface::Target);
            EXPECT_NEAR(e.position.z, -10 + 0.025, 1e-6);
            EXPECT_NEAR(e.normal.z, 1.0, 1e-9);
        }
    // Down, it is not hit; after its 3 s reset it rises with full health.
    EXPECT_EQ(count(tapShots(sim, 1, 20), SimEventType::TargetHit), 0);
    for (int t = 0; t < 200; ++t) sim.step({});
    EXPECT_TRUE(sim.targets()[0].up);
    EXPECT_DOUBLE_EQ(sim.targets()[0].raise, 1.0);
}

TEST(CombatHits, AWallInFrontOfTheTargetTakesTheShot) {
    auto level = rangeLevel();
    level.brushes.push_back(box({-2, 0, -6}, {2, 3, -5.75}));  // a 25 cm wall 5 m ahead
    Simulation sim(level, aimedAt(-1.5));
    const auto events = tapShots(sim, 3, 20);
    EXPECT_EQ(count(events, SimEventType::TargetHit), 0);
    ASSERT_EQ(count(events, SimEventType::Impact), 3);
    for (const auto& e : events)
        if (e.type == SimEventType::Impact) {
            EXPECT_EQ(e.surface, Surface::Level);
            EXPECT_NEAR(e.position.z, -5.75, 5e-3);  // Bullet's ray hits are mm-accurate
        }
}

TEST(CombatSpread, SameSeedSameShotsOtherSeedOthers) {
    auto shots = [](std::uint64_t seed) {
        auto level = floorLevel();
        level.brushes.push_back(box({-20, 0, -30}, {20, 10, -29}));  // a backstop
        SimConfig c = aimedAt();
        c.seed = seed;
        Simulation sim(level, c);
        std::vector<Vec3> points;
        for (int t = 0; t < 300; ++t) {  // full auto: bloom and recoil make every shot different
            sim.step(fire());
            for (const auto& e : sim.events())
                if (e.type == SimEventType::Impact) points.push_back(e.position);
        }
        return points;
    };
    const auto a = shots(7), b = shots(7), c = shots(8);
    ASSERT_EQ(a.size(), 30u);  // one magazine, then the reload
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << i;
    int differ = 0;
    for (std::size_t i = 0; i < a.size() && i < c.size(); ++i) differ += !(a[i] == c[i]);
    EXPECT_GT(differ, 25);
}

TEST(WeaponRate, TenShotsASecondThirtyAMagazineTwoSecondReload) {
    Simulation sim(floorLevel(), aimedAt());
    int shots = 0;
    for (int t = 0; t < 60; ++t) {
        sim.step(fire());
        shots += count(sim.events(), SimEventType::Shot);
    }
    EXPECT_EQ(shots, 10);
    int reloadStart = -1, reloadEnd = -1;
    for (int t = 0; t < 400; ++t) {
        sim.step(fire());
        if (count(sim.events(), SimEventType::ReloadStart) && reloadStart < 0) reloadStart = t;
        if (count(sim.events(), SimEventType::ReloadEnd) && reloadEnd < 0) reloadEnd = t;
        if (reloadStart < 0) shots += count(sim.events(), SimEventType::Shot);
        if (reloadEnd >= 0) break;
    }
    EXPECT_EQ(shots, 30);  // the magazine emptied, then the reload started by itself
    EXPECT_EQ(reloadEnd - reloadStart, 120);  // 2 s at 60 Hz
    EXPECT_EQ(sim.weapon().magazine, 29);     // refilled, and the held trigger fired again at once
    EXPECT_EQ(sim.weapon().reserve, 90);
}

TEST(WeaponRate, EmptyWithNoReserveDryFiresOncePerPress) {
    Simulation sim(floorLevel(), aimedAt());
    int dry = 0;
    for (int t = 0; t < 60 * 40 && sim.weapon().magazine + sim.weapon().reserve > 0; ++t) sim.step(fire());
    for (int t = 0; t < 10; ++t) sim.step({});  // let go of the trigger
    for (int press = 0; press < 3; ++press)
        for (int t = 0; t < 10; ++t) {
            sim.step(t < 5 ? fire() : PlayerCommand{});
            dry += count(sim.events(), SimEventType::DryFire);
            EXPECT_EQ(count(sim.events(), SimEventType::Shot), 0);
        }
    EXPECT_EQ(dry, 3);
}

TEST(WeaponRecoil, KicksTheViewUpAndRecovers) {
    Simulation sim(floorLevel(), aimedAt());
    const double start = sim.player().pitch;
    for (int t = 0; t < 30; ++t) sim.step(fire());
    EXPECT_GT(sim.player().pitch - start, 0.02);  // a burst climbs (>1 degree)
    for (int t = 0; t < 120; ++t) sim.step({});
    EXPECT_NEAR(sim.player().pitch, start, 1e-4);  // and comes back down
}

TEST(CombatProps, ShotCrateMovesShotBarrelFalls) {
    auto level = floorLevel();
    level.entities.push_back(crate({0, 0, -4}));
    level.entities.push_back(pointEntity("prop_barrel", {0, 0, -8}));
    // Crate: aim at its upper half (0.4-0.75 m) from the eye at 1.65 m, 4 m away.
    Simulation sim(level, aimedAt(-std::atan(1.1 / 3.6) * 180 / kPi));
    const Vec3 crate0 = sim.bodyPoses()[0].position;
    const auto events = tapShots(sim, 2, 20);
    EXPECT_EQ(count(events, SimEventType::PropHit), 2);
    for (int t = 0; t < 60; ++t) sim.step({});
    EXPECT_GT(length(sim.bodyPoses()[0].position - crate0), 0.1);
    EXPECT_EQ(sim.bodyPoses()[1].shape, Simulation::BodyPose::Shape::Cylinder);

    auto barrelLevel = floorLevel();
    barrelLevel.entities.push_back(pointEntity("prop_barrel", {0, 0, -4}));
    Simulation sim2(barrelLevel, aimedAt(-std::atan(0.85 / 3.7) * 180 / kPi));  // near its top (0.8 m)
    tapShots(sim2, 3, 15);
    for (int t = 0; t < 90; ++t) sim2.step({});
    const auto& p = sim2.bodyPoses()[0];
    // Its axis (local Y) rotated: tipped more than 45 degrees.
    const double upY = 1 - 2 * (p.qx * p.qx + p.qz * p.qz);
    EXPECT_LT(upY, std::cos(kPi / 4)) << "barrel still standing";
}

TEST(TargetMoving, SlidesBetweenItsEnds) {
    auto level = floorLevel();
    level.entities.push_back(pointEntity("target_moving", {0, 0, -10}, kPi, {{"distance", "4"}, {"speed", "2"}}));
    Simulation sim(level, aimedAt());
    double lo = 1e9, hi = -1e9;
    for (int t = 0; t < 600; ++t) {
        sim.step({});
        lo = std::min(lo, sim.targets()[0].position.x);
        hi = std::max(hi, sim.targets()[0].position.x);
    }
    EXPECT_NEAR(lo, -2, 0.05);
    EXPECT_NEAR(hi, 2, 0.05);
}

TEST(TargetEntities, BadKeysNameTheFile) {
    auto level = floorLevel();
    auto e = pointEntity("target_popup", {0, 0, -5}, 0, {{"width", "wide"}});
    e.pos = {12, 3};
    level.entities.push_back(e);
    try {
        Simulation sim(level, aimedAt());
        FAIL() << "accepted width 'wide'";
    } catch (const SimError& err) {
        EXPECT_NE(std::string(err.what()).find("test.map:12:3"), std::string::npos) << err.what();
        EXPECT_NE(std::string(err.what()).find("width"), std::string::npos) << err.what();
    }
}

namespace {
// Holds G for `holdTicks`, releases, and follows the grenade until it detonates.
struct Throw {
    double distance = 0;  // horizontal, from the eye to where it went off
    int bounces = 0;
    bool detonated = false;
    Vec3 at;
};
Throw throwGrenade(Simulation& sim, int holdTicks) {
    Throw r;
    const Vec3 eye = sim.player().eye();
    PlayerCommand hold;
    hold.throwHeld = true;
    for (int t = 0; t < holdTicks; ++t) sim.step(hold);
    for (int t = 0; t < 200 && !r.detonated; ++t) {
        sim.step({});
        for (const auto& e : sim.events()) {
            r.bounces += e.type == SimEventType::GrenadeBounce;
            if (e.type == SimEventType::GrenadeDetonate) {
                r.detonated = true;
                r.at = e.position;
            }
        }
    }
    r.distance = std::hypot(r.at.x - eye.x, r.at.z - eye.z);
    return r;
}
}  // namespace

TEST(GrenadeThrow, LongerHoldThrowsFurtherItBouncesAndGoesOffAfterTwoSeconds) {
    auto level = floorLevel();
    Simulation shortThrow(level, aimedAt(10)), longThrow(level, aimedAt(10));
    const Throw a = throwGrenade(shortThrow, 5), b = throwGrenade(longThrow, 60);
    ASSERT_TRUE(a.detonated);
    ASSERT_TRUE(b.detonated);
    EXPECT_GT(b.distance, a.distance + 3);
    EXPECT_GT(a.bounces, 0);
    EXPECT_LT(a.at.y, 0.2);  // it lies on the floor when it goes off
    EXPECT_TRUE(shortThrow.grenades().empty());
}

TEST(GrenadeThrow, NeverPassesThroughAOneBrushWall) {
    for (int angle = -40; angle <= 40; angle += 20)
        for (int pitch : {-5, 5, 20}) {
            auto level = floorLevel();
            level.brushes.push_back(box({-10, 0, -2.25}, {10, 6, -2}));  // 25 cm wall 2 m ahead
            SimConfig c = aimedAt(pitch);
            c.startYaw = angle * kPi / 180;
            Simulation sim(level, c);
            const Throw r = throwGrenade(sim, 60);  // the hardest throw
            ASSERT_TRUE(r.detonated);
            EXPECT_GT(r.at.z, -2.0) << "through the wall at yaw " << angle << " pitch " << pitch;
        }
}

TEST(CombatCues, FootstepsWhileWalkingNoneStandingEventsClearedEachTick) {
    Simulation sim(floorLevel(), aimedAt());
    int steps = 0;
    for (int t = 0; t < 60; ++t) {
        sim.step({});
        steps += count(sim.events(), SimEventType::Footstep);
    }
    EXPECT_EQ(steps, 0);
    for (int t = 0; t < 120; ++t) {
        sim.step(walk());
        steps += count(sim.events(), SimEventType::Footstep);
    }
    EXPECT_GE(steps, 3);  // ~9 m in 2 s: a step every 2.2 m
    sim.step(fire());
    EXPECT_EQ(count(sim.events(), SimEventType::Shot), 1);
    sim.step({});
    EXPECT_EQ(count(sim.events(), SimEventType::Shot), 0);
}

TEST(CombatDeterminism, SameSeedAndCommandsSameHashEveryTick) {
    auto level = rangeLevel();
    level.entities.push_back(crate({2, 0, -5}));
    auto run = [&level](std::vector<std::string>& hashes) {
        Simulation sim(level, aimedAt(-1.5));
        for (int t = 0; t < 200; ++t) {
            PlayerCommand c;
            c.fire = t % 7 < 3;
            c.throwHeld = t >= 50 && t < 80;
            c.forward = t > 120 ? 1.0f : 0.0f;
            c.yawDelta = t % 40 < 20 ? 0.01f : -0.01f;
            sim.step(c);
            hashes.push_back(sim.stateHashHex());
        }
    };
    std::vector<std::string> a, b;
    run(a);
    run(b);
    EXPECT_EQ(a, b);
    Simulation quiet(level, aimedAt(-1.5)), shooting(level, aimedAt(-1.5));
    quiet.step({});
    shooting.step(fire());
    EXPECT_NE(quiet.stateHashHex(), shooting.stateHashHex());
}

