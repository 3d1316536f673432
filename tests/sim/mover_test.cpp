// Movers and triggers (sim/movers.h, sim/triggers.h) on hand-built levels: Quake's timings in
// ticks, the player carried and pushed, targets fired, determinism.
#include "sim_test_levels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

using namespace obscura;
using namespace obscura::sim;
using namespace obscura::sim::testlevels;

namespace {
constexpr double kUpm = 32;  // units per metre of the test levels (Quake's default)

// A door 2 m wide (64 u), 2.5 m tall, 0.25 m thick across z = -5, sliding +X (angle 0).
const std::pair<Vec3, Vec3> kDoorBox{{-1, 0, -5.125}, {1, 2.5, -4.875}};
// Quake: moves 64 - 8 = 56 u at 100 u/s.
const double kDoorTravel = 56 / kUpm;
const int kDoorTicks = static_cast<int>(std::ceil(kDoorTravel / (100 / kUpm / 60)));  // 34

int ticksUntil(Simulation& s, const std::function<bool()>& done, int limit, const PlayerCommand& c = {}) {
    for (int t = 1; t <= limit; ++t) {
        s.step(c);
        if (done()) return t;
    }
    return -1;
}
}  // namespace

TEST(Movers, DoorOpensForANearPlayerWaitsThreeSecondsAndCloses) {
    map::Level l = floorLevel();
    addEntity(l, "func_door", {{"angle", "0"}}, {kDoorBox});
    // In the trigger field (60 u = 1.875 m in front of the door), then walking back out of it.
    Simulation s(l, startAt({0, 0, -3.2}));
    ASSERT_EQ(s.movers().count(), 1u);
    EXPECT_NEAR(s.movers().openOffset(0).x, kDoorTravel, 1e-9);
    s.step(walk(-1));
    const int opened = ticksUntil(s, [&] { return s.movers().offset(0).x >= kDoorTravel; }, 100, walk(-1));
    EXPECT_EQ(opened + 1, kDoorTicks);
    EXPECT_GT(s.player().feet.z, -1.5);  // walked out of the field
    // Waits 3 s = 180 ticks at the top, then closes in the same time it opened.
    run(s, {}, 179);
    EXPECT_DOUBLE_EQ(s.movers().offset(0).x, kDoorTravel);
    const int closed = ticksUntil(s, [&] { return s.movers().offset(0).x <= 0; }, 100);
    EXPECT_EQ(closed, kDoorTicks);  // the move starts 180 ticks after the door stopped
    EXPECT_DOUBLE_EQ(s.movers().offset(0).x, 0.0);
}

TEST(Movers, TargetedDoorIgnoresThePlayerAndOpensFromATriggerOnce) {
    map::Level l = floorLevel();
    addEntity(l, "func_door", {{"angle", "-1"}, {"targetname", "gate"}, {"wait", "-1"}}, {kDoorBox});
    addEntity(l, "trigger_once", {{"target", "gate"}}, {{{2, 0, -4}, {3, 2, -3}}});
    Simulation s(l, startAt({0, 0, -3.5}));
    run(s, {}, 30);
    EXPECT_EQ(s.movers().offset(0), Vec3{});  // no trigger field on a targeted door
    // Strafe +X into the trigger: the door goes up (angle -1) by its 80 u height - 8 u lip.
    ASSERT_GT(ticksUntil(s, [&] { return s.movers().offset(0) != Vec3{}; }, 120, walk(0, 1)), 0);
    EXPECT_GT(s.movers().offset(0).y, 0);
    EXPECT_TRUE(s.triggers().removed(0));  // trigger_once: gone once fired
    run(s, {}, 400);
    EXPECT_NEAR(s.movers().offset(0).y, (80 - 8) / kUpm, 1e-9);  // wait -1: stays open
}

TEST(Movers, ButtonPressedByTouchFiresItsTargetAndComesBack) {
    map::Level l = floorLevel();
    addEntity(l, "func_door", {{"angle", "0"}, {"targetname", "d"}}, {kDoorBox});
    // A 0.25 m (8 u) deep button on the +X side, moving +X by 8 - 4 = 4 u at 40 u/s (0.1 s).
    addEntity(l, "func_button", {{"angle", "0"}, {"target", "d"}}, {{{2, 0.8, -0.25}, {2.25, 1.4, 0.25}}});
    Simulation s(l, startAt({1.2, 0, 0}, -kPi / 2));
    const int pressed = ticksUntil(s, [&] { return s.movers().offset(1).x > 0; }, 60, walk());
    ASSERT_GT(pressed, 0);
    const int fired = ticksUntil(s, [&] { return s.movers().offset(0).x > 0; }, 60);
    EXPECT_NEAR(fired, 6 + 1, 1);  // 4 u at 40 u/s = 6 ticks in, the door moves the tick after
    EXPECT_NEAR(s.movers().offset(1).x, 4 / kUpm, 1e-9);
    // wait 1 s, then back out (6 ticks).
    const int back = ticksUntil(s, [&] { return s.movers().offset(1).x == 0; }, 200, walk(-1));
    EXPECT_NEAR(back, 60 + 6, 3);
}

TEST(Movers, TouchingDoorsLinkAndOpenTogether) {
    map::Level l = floorLevel();
    addEntity(l, "func_door", {{"angle", "180"}, {"targetname", "pair"}}, {{{-1, 0, -5.125}, {0, 2.5, -4.875}}});
    addEntity(l, "func_door", {{"angle", "0"}}, {{{0, 0, -5.125}, {1, 2.5, -4.875}}});
    addEntity(l, "func_door", {{"angle", "0"}, {"spawnflags", "4"}}, {{{1, 0, -5.125}, {2, 2.5, -4.875}}});  // DONT_LINK
    addEntity(l, "trigger_once", {{"target", "pair"}}, {{{-1, 0, -1}, {1, 2, 1}}});
    Simulation s(l, startAt({0, 0, 0}));
    run(s, {}, 60);
    EXPECT_NEAR(s.movers().offset(0).x, -(32 - 8) / kUpm, 1e-9);
    EXPECT_NEAR(s.movers().offset(1).x, (32 - 8) / kUpm, 1e-9);  // linked: opened though not named
    EXPECT_EQ(s.movers().offset(2), Vec3{});                      // DONT_LINK; far from the player: closed
}

TEST(Movers, PlatRisesWithItsRiderWaitsAndGoesDown) {
    map::Level l = floorLevel();
    // Built at the top (2 m); rests 2 m - 8 u lower. A 2 m ledge beside it to step off onto.
    addEntity(l, "func_plat", {}, {{{-1, 0, -1}, {1, 2, 1}}});
    l.brushes.push_back(box({1, 0, -1}, {4, 2, 1}));
    const double travel = 2 - 8 / kUpm;
    Simulation s(l, startAt({0, 0.3, 0}));
    EXPECT_NEAR(s.movers().offset(0).y, -travel, 1e-9);
    // Lands on it (in the inside trigger): it rises at 150 u/s with the player on it.
    const int top = ticksUntil(s, [&] { return s.movers().offset(0).y >= 0; }, 120);
    ASSERT_GT(top, 0);
    EXPECT_NEAR(s.player().feet.y, 2.0, 0.02);
    EXPECT_TRUE(s.player().onGround || s.player().velocity.y > -1);
    // Step off east onto the ledge; the plat goes down 3 s after reaching the top (at least 1 s after the player left).
    run(s, walk(0, 1), 40);
    EXPECT_GT(s.player().feet.x, 1.4);
    EXPECT_NEAR(s.player().feet.y, 2.0, 0.02);
    const int down = ticksUntil(s, [&] { return s.movers().offset(0).y <= -travel; }, 400);
    ASSERT_GT(down, 0);
    EXPECT_NEAR(down + 40, 180 + static_cast<int>(std::ceil(travel / (150 / kUpm / 60))), 2);
}

TEST(Movers, TrainFollowsItsPathCornersWithTheirWaits) {
    map::Level l = floorLevel();
    addEntity(l, "func_train", {{"target", "a"}}, {{{-0.5, 5, -0.5}, {0.5, 6, 0.5}}});
    addPoint(l, "path_corner", {0, 5, 0}, 0, {{"targetname", "a"}, {"target", "b"}});
    addPoint(l, "path_corner", {2, 5, 0}, 0, {{"targetname", "b"}, {"target", "a"}, {"wait", "0.5"}});
    Simulation s(l, startAt({5, 0, 5}));
    // Quake's mins corner (min x, min y, max z here) sits on corner a.
    EXPECT_NEAR(s.movers().offset(0).x, 0.5, 1e-9);
    EXPECT_NEAR(s.movers().offset(0).z, -0.5, 1e-9);
    const int atB = ticksUntil(s, [&] { return s.movers().offset(0).x >= 2.5; }, 200);
    // 0.1 s start, then 2 m at 100 u/s (3.125 m/s): 6 + 39 ticks.
    EXPECT_NEAR(atB, 6 + 39, 1);
    run(s, {}, 29);
    EXPECT_DOUBLE_EQ(s.movers().offset(0).x, 2.5);  // waits 0.5 s at b
    const int backAtA = ticksUntil(s, [&] { return s.movers().offset(0).x <= 0.5; }, 200);
    EXPECT_NEAR(backAtA, 1 + 39, 1);
}

TEST(Triggers, TeleportPlacesThePlayerAtTheDestinationFacingItsAngle) {
    map::Level l = floorLevel();
    addEntity(l, "trigger_teleport", {{"target", "there"}}, {{{-1, 0, -3}, {1, 2, -2}}});
    addPoint(l, "info_teleport_destination", {10, 0, 10}, kPi / 2, {{"targetname", "there"}, {"angle", "180"}});
    Simulation s(l, startAt({0, 0, 0}));
    bool teleported = false;
    for (int t = 0; t < 120 && !teleported; ++t) {
        s.step(walk());
        for (const auto& e : s.events()) teleported |= e.type == SimEventType::Teleport;
    }
    ASSERT_TRUE(teleported);
    EXPECT_NEAR(s.player().feet.x, 10, 1e-6);
    EXPECT_NEAR(s.player().feet.z, 10, 1e-6);
    EXPECT_NEAR(s.player().feet.y, 3 / kUpm, 1e-6);
    EXPECT_NEAR(s.player().yaw, kPi / 2, 1e-6);
    // The speed goes on along the new yaw (facing -X).
    EXPECT_LT(s.player().velocity.x, -1);
    EXPECT_NEAR(s.player().velocity.z, 0, 1e-9);
}

TEST(Triggers, PushSetsTheVelocityAlongItsAngle) {
    map::Level l = floorLevel();
    addEntity(l, "trigger_push", {{"angle", "-1"}, {"speed", "100"}}, {{{-1, 0, -1}, {1, 0.5, 1}}});
    addEntity(l, "trigger_push", {{"angle", "90"}, {"speed", "50"}, {"spawnflags", "1"}}, {{{-1, 0, 5}, {1, 2, 6}}});
    Simulation s(l, startAt({0, 0, 0}));
    s.step({});
    EXPECT_DOUBLE_EQ(s.player().velocity.y, 100 * 10 / kUpm);  // Quake: speed x 10 u/s, up
    EXPECT_NEAR(s.player().velocity.x, 0, 1e-12);
    Simulation s2(l, startAt({0, 0, 5.5}));
    s2.step({});
    EXPECT_NEAR(s2.player().velocity.z, -50 * 10 / kUpm, 1e-9);  // angle 90: Quake +Y, world -Z
    EXPECT_TRUE(s2.triggers().removed(1));                       // PUSH_ONCE
}

TEST(Movers, DoorClosingOnAPinnedPlayerGoesBack) {
    map::Level l = floorLevel();
    // START_OPEN: rests open (+1.75 m); targeted, it closes towards -X onto the player, who stands
    // against a wall at x = -1.2.
    addEntity(l, "func_door", {{"angle", "0"}, {"spawnflags", "1"}, {"targetname", "d"}}, {{{-1, 0, -0.125}, {1, 2.5, 0.125}}});
    addEntity(l, "trigger_once", {{"target", "d"}}, {{{-1, 0, -1}, {1, 2, 1}}});
    l.brushes.push_back(box({-1.6, 0, -3}, {-1.2, 3, 3}));
    Simulation s(l, startAt({-0.5, 0, 0}));
    double closest = 1e9;
    bool reopened = false;
    double last = s.movers().offset(0).x;
    for (int t = 0; t < 300; ++t) {
        s.step({});
        const double x = s.movers().offset(0).x;
        closest = std::min(closest, x);
        reopened |= x > last + 1e-9;
        last = x;
        EXPECT_GE(s.player().feet.x, -1.2 + kRadius - 0.015);  // never crushed into the wall
    }
    EXPECT_TRUE(reopened);
    EXPECT_GT(closest, 0.2);  // stopped at the player (door face at -1 + x, player at -1.2 + 0.7)
    EXPECT_NEAR(s.movers().offset(0).x, kDoorTravel, 1e-9);  // back open
}

TEST(Movers, SecretDoorGoesSidewaysThenBackAndReturns) {
    map::Level l = floorLevel();
    // Facing angle 90 (into -Z): first right (+X... makevectors' right of +Y is +X) by its width 2 m,
    // then along the angle by its depth 0.25 m.
    addEntity(l, "func_door_secret", {{"angle", "90"}, {"targetname", "s"}, {"wait", "1"}}, {kDoorBox});
    addEntity(l, "trigger_once", {{"target", "s"}}, {{{-1, 0, -1}, {1, 2, 1}}});
    Simulation s(l, startAt({0, 0, 0}));
    const double speed = 50 / kUpm / 60;
    const int first = static_cast<int>(std::ceil(2 / speed));
    run(s, {}, first + 1);
    EXPECT_NEAR(s.movers().offset(0).x, 2, 1e-9);
    EXPECT_NEAR(s.movers().offset(0).z, 0, 1e-9);
    run(s, {}, 60 + static_cast<int>(std::ceil(0.25 / speed)) + 1);
    EXPECT_NEAR(s.movers().offset(0).z, -0.25, 1e-9);
    run(s, {}, 1000);
    EXPECT_EQ(s.movers().offset(0), Vec3{});  // home again
}

TEST(Movers, SameCommandsGiveTheSameHashEveryTick) {
    auto level = [] {
        map::Level l = floorLevel();
        addEntity(l, "func_door", {{"angle", "0"}}, {kDoorBox});
        addEntity(l, "func_plat", {}, {{{3, 0, -1}, {5, 2, 1}}});
        addEntity(l, "func_train", {{"target", "a"}}, {{{-0.5, 5, -0.5}, {0.5, 6, 0.5}}});
        addPoint(l, "path_corner", {0, 5, 0}, 0, {{"targetname", "a"}, {"target", "b"}});
        addPoint(l, "path_corner", {2, 5, 3}, 0, {{"targetname", "b"}, {"target", "a"}});
        addEntity(l, "trigger_multiple", {{"target", "a"}}, {{{-1, 0, -3}, {1, 2, -2}}});
        return l;
    }();
    Simulation a(level, startAt({0, 0, 0})), b(level, startAt({0, 0, 0}));
    std::vector<std::uint64_t> seen;
    for (int t = 0; t < 600; ++t) {
        PlayerCommand c = walk(t < 200 ? 1.0f : -1.0f, t % 90 < 45 ? 0.5f : -0.5f);
        a.step(c);
        b.step(c);
        ASSERT_EQ(a.stateHash(), b.stateHash()) << "tick " << t;
        seen.push_back(a.stateHash());
    }
    // Cost, for the README (not asserted: machines differ): the same walk with and without the movers.
    auto timed = [](const map::Level& lv) {
        Simulation sim(lv, startAt({0, 0, 0}));
        const auto t0 = std::chrono::steady_clock::now();
        for (int t = 0; t < 600; ++t) sim.step(walk(t < 200 ? 1.0f : -1.0f, t % 90 < 45 ? 0.5f : -0.5f));
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / 600;
    };
    std::cout << "ms a tick: with 3 movers and a trigger " << timed(level) << ", without " << timed(floorLevel()) << "\n";
    // The movers are in the hash: the same player state with the door elsewhere hashes apart.
    std::sort(seen.begin(), seen.end());
    EXPECT_EQ(std::unique(seen.begin(), seen.end()), seen.end());
}

TEST(Movers, BadInputIsAWarningAndTheLevelStillLoads) {
    map::Level l = floorLevel();
    addEntity(l, "func_door", {{"angle", "0"}}, {}, 11);                                            // no brushes
    addEntity(l, "func_door", {{"speed", "fast"}, {"target", "nobody"}}, {kDoorBox}, 22);          // bad speed, target
    addEntity(l, "func_train", {{"target", "nowhere"}}, {{{-0.5, 5, -0.5}, {0.5, 6, 0.5}}}, 33);   // no path_corner
    addEntity(l, "trigger_teleport", {{"target", "void"}}, {{{5, 0, 5}, {6, 2, 6}}}, 44);          // no destination
    Simulation s(l, startAt({0, 0, -3}));
    std::string all;
    for (const auto& w : s.warnings()) all += w + "\n";
    EXPECT_NE(all.find("test.map:11: func_door: has no brushes"), std::string::npos) << all;
    EXPECT_NE(all.find("test.map:22: func_door: 'speed' value 'fast' is not a number"), std::string::npos) << all;
    EXPECT_NE(all.find("test.map:22: func_door: 'target' 'nobody' names no entity"), std::string::npos) << all;
    EXPECT_NE(all.find("test.map:33: func_train: target 'nowhere' names no path_corner"), std::string::npos) << all;
    EXPECT_NE(all.find("test.map:44: trigger_teleport: no info_teleport_destination named 'void'"), std::string::npos) << all;
    EXPECT_EQ(s.movers().count(), 2u);
    run(s, {}, 60);  // and it plays: the bad-speed door (the player in its field) opened at the default speed
    EXPECT_NEAR(s.movers().offset(0).x, kDoorTravel, 1e-9);
}

TEST(Movers, AShootableDoorOpensWhenShot) {
    map::Level l = floorLevel();
    addEntity(l, "func_door", {{"angle", "-1"}, {"health", "10"}}, {kDoorBox});
    Simulation s(l, startAt({0, 0, -1}));  // 3.9 m from the door, outside its (absent) field
    run(s, {}, 10);
    EXPECT_EQ(s.movers().offset(0), Vec3{}) << "a shootable door has no trigger field";
    PlayerCommand fire;
    fire.fire = true;
    s.step(fire);
    run(s, {}, 5);
    EXPECT_GT(s.movers().offset(0).y, 0);
}

TEST(Triggers, MultipleRefiresAfterItsWaitRelayDelayAndKilltarget) {
    map::Level l = floorLevel();
    // A trigger_multiple (wait 1 s) under the player fires a relay with a 0.5 s delay that opens
    // a toggle door; the second firing closes it again. A trigger_once far away is killtargeted.
    addEntity(l, "func_door", {{"angle", "-1"}, {"targetname", "d"}, {"spawnflags", "32"}}, {kDoorBox});
    addEntity(l, "trigger_multiple", {{"target", "relay"}, {"wait", "1"}, {"killtarget", "far"}}, {{{-1, 0, -1}, {1, 2, 1}}});
    addEntity(l, "trigger_relay", {{"targetname", "relay"}, {"target", "d"}, {"delay", "0.5"}});
    addEntity(l, "trigger_once", {{"targetname", "far"}, {"target", "d"}}, {{{10, 0, 10}, {11, 2, 11}}});
    Simulation s(l, startAt({0, 0, 0}));
    s.step({});
    EXPECT_TRUE(s.triggers().removed(2)) << "killtarget";
    run(s, {}, 29);
    EXPECT_EQ(s.movers().offset(0), Vec3{}) << "the relay's delay";
    run(s, {}, 2);
    EXPECT_GT(s.movers().offset(0).y, 0) << "opened 0.5 s after the first firing";
    run(s, {}, 60);  // the trigger fired again at 1 s: the toggle door goes back down 0.5 s later
    const double top = s.movers().offset(0).y;
    run(s, {}, 10);
    EXPECT_LT(s.movers().offset(0).y, top);
}

TEST(Triggers, CounterFiresOnItsCountthUse) {
    map::Level l = floorLevel();
    addEntity(l, "func_door", {{"angle", "-1"}, {"targetname", "d"}, {"wait", "-1"}}, {kDoorBox});
    addEntity(l, "trigger_counter", {{"targetname", "c"}, {"target", "d"}, {"count", "3"}});
    addEntity(l, "trigger_multiple", {{"target", "c"}, {"wait", "0.5"}}, {{{-1, 0, -1}, {1, 2, 1}}});
    Simulation s(l, startAt({0, 0, 0}));
    run(s, {}, 60);  // used in ticks 1 and 31; the third use comes in tick 61
    EXPECT_EQ(s.movers().offset(0), Vec3{});
    run(s, {}, 2);
    EXPECT_GT(s.movers().offset(0).y, 0) << "the third use fires it";
}

TEST(Triggers, AnglesZeroMinusOneZeroIsUpAsAngleMinusOne) {
    map::Level l = floorLevel();
    addEntity(l, "trigger_push", {{"angles", "0 -1 0"}, {"speed", "40"}}, {{{-1, 0, -1}, {1, 0.5, 1}}});
    addEntity(l, "trigger_push", {{"angles", "-90 0 0"}, {"speed", "40"}}, {{{4, 0, -1}, {6, 0.5, 1}}});  // pitched up
    Simulation a(l, startAt({0, 0, 0})), b(l, startAt({5, 0, 0}));
    a.step({});
    b.step({});
    EXPECT_DOUBLE_EQ(a.player().velocity.y, 40 * 10 / kUpm);
    EXPECT_NEAR(b.player().velocity.y, 40 * 10 / kUpm, 1e-9);
    EXPECT_NEAR(b.player().velocity.x, 0, 1e-9);
}
