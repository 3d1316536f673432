// Swimming and liquid damage (player_controller.cpp's swimming section, Simulation): the player
// sinks slowly when idle, swims up with jump, swims no faster than 0.7 of the run, wades slower,
// jumps out at an edge, takes Quake's slime and lava damage, and all of it replays bit for bit.
#include <gtest/gtest.h>

#include "map/map_compile.h"
#include "sim_test_levels.h"

#include <cmath>
#include <string>

using namespace obscura;
using namespace obscura::sim;
using namespace obscura::sim::testlevels;

namespace {
// The floor slab (top y = 0) under `depth` metres of a liquid.
map::Level pool(double depth, map::LiquidKind kind = map::LiquidKind::Water) {
    map::Level l = floorLevel();
    l.brushes.push_back(liquidBox({-20, 0, -20}, {20, depth, 20}, kind));
    return l;
}

double horizontalSpeed(const Simulation& s) { return std::hypot(s.player().velocity.x, s.player().velocity.z); }

PlayerCommand jump() {
    PlayerCommand c;
    c.jump = true;
    return c;
}
}  // namespace

TEST(Swim, WaterLevelsFollowQuake) {
    Simulation dry(floorLevel(), {});
    dry.step({});
    EXPECT_EQ(dry.player().waterLevel, 0);
    Simulation feet(pool(0.3), {});
    feet.step({});
    EXPECT_EQ(feet.player().waterLevel, 1);
    EXPECT_EQ(feet.player().liquid, map::LiquidKind::Water);
    Simulation waist(pool(1.2), {});
    waist.step({});
    EXPECT_EQ(waist.player().waterLevel, 2);
    Simulation under(pool(3), {});
    under.step({});
    EXPECT_EQ(under.player().waterLevel, 3);
}

TEST(Swim, IdleInDeepWaterSinksSlowly) {
    Simulation s(pool(3), startAt({0, 1.0, 0}));
    run(s, {}, 20);
    const double sink = SwimTuning{}.sinkSpeed;  // 1.875 m/s
    EXPECT_LT(s.player().velocity.y, -0.5 * sink);  // going down...
    EXPECT_GT(s.player().velocity.y, -1.05 * sink);  // ...no faster than the drift (a fall: 25 m/s)
    EXPECT_GT(s.player().feet.y, 1.0 - sink / 3);    // at most the drift's 0.625 m in a third of a second
    EXPECT_LT(s.player().feet.y, 1.0 - 0.3 * sink / 3);
    run(s, {}, 120);  // settles on the bottom
    EXPECT_NEAR(s.player().feet.y, 0.0, 0.02);
    EXPECT_TRUE(s.player().onGround);
}

TEST(Swim, JumpSwimsUpToTheSurfaceAndBobsThere) {
    Simulation s(pool(3), startAt({0, 0.2, 0}));
    run(s, jump(), 30);
    EXPECT_GT(s.player().velocity.y, 1.0);
    EXPECT_LE(s.player().velocity.y, 0.7 * PlayerTuning{}.walkSpeed + 1e-9);
    EXPECT_GT(s.player().feet.y, 0.6);
    // Held on: the player rises until the waist leaves the water, falls back, and stays about there.
    double low = 1e9, high = -1e9;
    for (int i = 0; i < 240; ++i) {
        s.step(jump());
        if (i >= 120) {
            low = std::min(low, s.player().feet.y);
            high = std::max(high, s.player().feet.y);
        }
    }
    const double waistAtSurface = 3.0 - PlayerTuning{}.standHeight / 2;  // 2.1
    EXPECT_GT(low, waistAtSurface - 0.6);
    EXPECT_LT(high, waistAtSurface + 0.6);
    EXPECT_GE(s.player().waterLevel, 1);
}

TEST(Swim, HorizontalSpeedIsCappedAtSevenTenthsOfTheRun) {
    Simulation s(pool(3), startAt({0, 1.0, 0}));
    run(s, walk(), 180);
    const double cap = 0.7 * PlayerTuning{}.walkSpeed;
    EXPECT_LE(horizontalSpeed(s), cap + 1e-9);
    EXPECT_GT(horizontalSpeed(s), 0.85 * cap);  // water friction costs a little of it
    Simulation dry(floorLevel(), {});
    run(dry, walk(), 180);
    EXPECT_GT(horizontalSpeed(dry), horizontalSpeed(s) * 1.3);
}

TEST(Swim, WadingIsSlowerThanWalking) {
    Simulation wade(pool(0.3), {}), dry(floorLevel(), {});
    run(wade, walk(), 120);
    run(dry, walk(), 120);
    EXPECT_EQ(wade.player().waterLevel, 1);
    EXPECT_TRUE(wade.player().onGround);
    EXPECT_LT(horizontalSpeed(wade), 0.95 * horizontalSpeed(dry));
    EXPECT_GT(horizontalSpeed(wade), 0.7 * horizontalSpeed(dry));
}

TEST(Swim, JumpsOutOfTheWaterAtAnEdge) {
    // Water 2 m deep south of a deck whose top (y = 2.25) stands 0.25 m above the surface; the
    // player swims north (-Z) with jump held and must end standing on the deck.
    map::Level l = floorLevel();
    l.brushes.push_back(box({-20, 0, -20}, {20, 2.25, -3}));
    l.brushes.push_back(liquidBox({-20, 0, -3}, {20, 2.0, 20}));
    Simulation s(l, startAt({0, 0.5, 0}));
    PlayerCommand c = walk();
    c.jump = true;
    bool jumped = false;
    for (int i = 0; i < 360 && !(s.player().onGround && s.player().feet.z < -3.4); ++i) {
        s.step(c);
        jumped |= s.player().waterJumpTime > 0;
    }
    EXPECT_TRUE(jumped);
    EXPECT_TRUE(s.player().onGround);
    EXPECT_NEAR(s.player().feet.y, 2.25, 0.02);
    EXPECT_LT(s.player().feet.z, -3.4);
    EXPECT_EQ(s.player().waterLevel, 0);
}

TEST(Swim, WalksUpAStepOutOfWaistDeepWater) {
    // Waist-deep water (swimming, level 2) ending at a 0.42 m step (above the capsule's round
    // bottom: it does not slide over it), north (-Z) of the player.
    map::Level l = floorLevel();
    l.brushes.push_back(box({-20, 0, -20}, {20, 0.42, -3}));
    l.brushes.push_back(liquidBox({-20, 0, -3}, {20, 1.2, 20}));
    Simulation s(l, {});
    s.step({});
    ASSERT_EQ(s.player().waterLevel, 2);
    run(s, walk(), 120);
    EXPECT_LT(s.player().feet.z, -3.5);
    EXPECT_NEAR(s.player().feet.y, 0.42, 0.02);
}

TEST(Swim, LavaAndSlimeHurtAsInQuake) {
    // Lava: 10 x waterlevel every 0.2 s; slime: 4 x waterlevel every second; water: nothing.
    Simulation lava(pool(0.3, map::LiquidKind::Lava), {});
    run(lava, {}, 60);  // hits at ticks 0, 12, 24, 36, 48
    EXPECT_EQ(lava.player().waterLevel, 1);
    EXPECT_EQ(lava.liquidDamage(), 50);
    EXPECT_EQ(lava.player().health, 50);
    Simulation slime(pool(1.2, map::LiquidKind::Slime), {});
    run(slime, {}, 120);  // waist deep (level 2): hits at ticks 0 and 60
    EXPECT_EQ(slime.liquidDamage(), 2 * 4 * 2);
    Simulation water(pool(3), {});
    run(water, {}, 120);
    EXPECT_EQ(water.liquidDamage(), 0);
    EXPECT_EQ(water.player().health, 100);
}

TEST(Swim, DeathInLavaRespawnsAtTheStart) {
    // Over the head (level 3): 30 every 0.2 s; the fourth hit (tick 36) kills.
    map::Level l = floorLevel();
    l.brushes.push_back(liquidBox({-20, 0, -20}, {20, 3, -2}, map::LiquidKind::Lava));
    Simulation s(l, startAt({0, 0, -5}));
    run(s, {}, 36);
    EXPECT_EQ(s.deaths(), 0);
    EXPECT_EQ(s.player().health, 10);
    s.step({});
    EXPECT_EQ(s.deaths(), 1);
    EXPECT_EQ(s.player().health, 100);
    EXPECT_NEAR(s.player().feet.z, -5, 1e-9);
}

TEST(Swim, SwimmingIsDeterministic) {
    const auto play = [](Simulation& s, std::vector<std::string>& hashes) {
        for (int i = 0; i < 240; ++i) {
            PlayerCommand c = walk(i % 90 < 60 ? 1.0f : 0.0f, i % 50 < 20 ? 0.5f : 0.0f);
            c.jump = i % 70 < 25;
            c.pitchDelta = i < 40 ? -0.01f : 0.004f;
            s.step(c);
            hashes.push_back(s.stateHashHex());
        }
    };
    Simulation a(pool(3), startAt({0, 1, 0})), b(pool(3), startAt({0, 1, 0}));
    std::vector<std::string> ha, hb;
    play(a, ha);
    play(b, hb);
    EXPECT_EQ(ha, hb);
    Simulation dry(floorLevel(), startAt({0, 1, 0}));
    std::vector<std::string> hd;
    play(dry, hd);
    EXPECT_NE(ha.back(), hd.back());
}

TEST(Swim, ThePoolLevelSwallowsThePlayer) {
    // tests/sim/levels/pool.map: walking forward off the deck ends in the water, over the floor.
    const map::Level level = map::loadLevel(std::string(OBSCURA_SOURCE_DIR) + "/tests/sim/levels/pool.map");
    Simulation s(level, {});
    EXPECT_EQ(s.liquids().size(), 1u);
    run(s, walk(), 90);
    EXPECT_GE(s.player().waterLevel, 2);
    EXPECT_GT(s.player().feet.y, -2.5 - 0.01);  // the pit's floor
    EXPECT_EQ(s.player().liquid, map::LiquidKind::Water);
}
