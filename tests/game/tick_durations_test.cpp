// Every presentation duration is set in seconds and converted with the run's tick rate, so at
// --tick-rate 30 and 120 an effect lasts the same wall-clock time (to within half a tick), and at
// 60 Hz the tick counts are exactly the ones the game was tuned with.
#include <gtest/gtest.h>

#include "game_smoke.h"
#include "map/map_compile.h"
#include "tick_durations.h"

#include <cmath>

using namespace obscura;

TEST(TickDurations, AtSixtyHertzTheTunedTickCounts) {
    const TickDurations d(60);
    EXPECT_EQ(d.headlessTicks, 300);
    EXPECT_EQ(d.sparkTicks, 12);
    EXPECT_EQ(d.muzzleFlashTicks, 2);
    EXPECT_EQ(d.smokeStepTicks, 3);
    EXPECT_EQ(d.hissFadeTicks, 30);
    EXPECT_EQ(d.hitMarkerFadePerTick, 1.0 / 15.0);  // bit for bit: the HUD's pixels do not move
    EXPECT_EQ(d.tickSeconds, 1.0 / 60.0);
}

TEST(TickDurations, ThirtyAndOneTwentyHertzLastTheSameSeconds) {
    for (const double rate : {30.0, 120.0}) {
        const TickDurations d(rate);
        const double halfTick = 0.5 / rate;
        auto seconds = [rate](double ticks) { return ticks / rate; };
        EXPECT_NEAR(seconds(static_cast<double>(d.headlessTicks)), kDefaultHeadlessSeconds, halfTick) << rate;
        EXPECT_NEAR(seconds(d.sparkTicks), kSparkSeconds, halfTick) << rate;
        EXPECT_NEAR(seconds(d.muzzleFlashTicks), kMuzzleFlashSeconds, halfTick) << rate;
        EXPECT_NEAR(seconds(d.smokeStepTicks), kSmokeStepSeconds, halfTick) << rate;
        EXPECT_NEAR(seconds(d.hissFadeTicks), kHissFadeSeconds, halfTick) << rate;
        // The hit marker fades from 1 to 0 in kHitMarkerFadeSeconds of ticks.
        double marker = 1.0;
        int ticks = 0;
        while (marker > 1e-9) {
            marker = std::max(0.0, marker - d.hitMarkerFadePerTick);
            ++ticks;
        }
        EXPECT_NEAR(seconds(ticks), kHitMarkerFadeSeconds, 1.0 / rate) << rate;
    }
    // The same wall-clock time at both rates.
    const TickDurations slow(30), fast(120);
    EXPECT_DOUBLE_EQ(slow.sparkTicks / 30.0, fast.sparkTicks / 120.0);
    EXPECT_DOUBLE_EQ(slow.headlessTicks / 30.0, fast.headlessTicks / 120.0);
    EXPECT_DOUBLE_EQ(slow.hissFadeTicks / 30.0, fast.hissFadeTicks / 120.0);
    EXPECT_DOUBLE_EQ(slow.muzzleFlashTicks / 30.0, fast.muzzleFlashTicks / 120.0);
}

TEST(TickDurations, SmokeStepsAtTheSameRateAndTimeWhateverTheTickRate) {
    // A cloud released at once, then one second of ticks: the smoke steps about 20 times and has
    // seen one second, at 30 and at 120 Hz.
    const map::Level level = map::loadLevel(std::string(OBSCURA_SOURCE_DIR) + "/media/levels/arena.map");
    for (const double rate : {30.0, 120.0}) {
        sim::SimConfig config;
        config.tickRate = rate;
        const sim::Simulation sim(level, config);
        GameSmoke smoke(level, {}, {0, 1, 0}, rate);
        smoke.spawn({31, 0.3, -30});  // the firing range (as smoke_inside.replay)
        for (int t = 0; t < static_cast<int>(rate); ++t) smoke.onTick({}, sim);
        ASSERT_EQ(smoke.manager().volumes().size(), 1u) << rate;
        EXPECT_NEAR(smoke.seconds(), 1.0, 1e-9) << rate;
        EXPECT_NEAR(static_cast<double>(smoke.version()), 1.0 / kSmokeStepSeconds, 5.0) << rate;
    }
}
