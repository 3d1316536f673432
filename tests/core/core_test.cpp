#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/fixed_step.h"
#include "core/rng.h"
#include "core/state_hash.h"

using namespace obscura;

TEST(Rng, SameSeedSameSequenceDifferentSeedDiffers) {
    Rng a(42), b(42), c(43);
    bool anyDiff = false;
    for (int i = 0; i < 100; ++i) {
        const auto x = a.nextU32();
        EXPECT_EQ(x, b.nextU32());
        anyDiff |= x != c.nextU32();
    }
    EXPECT_TRUE(anyDiff);
}

TEST(Rng, Uniform01StaysInRangeAndCoversIt) {
    Rng r(7);
    float lo = 1, hi = 0;
    double sum = 0;
    for (int i = 0; i < 100000; ++i) {
        const float f = r.uniform01();
        ASSERT_GE(f, 0.0f);
        ASSERT_LT(f, 1.0f);
        lo = std::min(lo, f);
        hi = std::max(hi, f);
        sum += f;
    }
    EXPECT_LT(lo, 0.001f);
    EXPECT_GT(hi, 0.999f);
    EXPECT_NEAR(sum / 100000.0, 0.5, 0.01);
}

TEST(Rng, BelowIsUnbiasedEnough) {
    Rng r(1);
    int counts[3] = {0, 0, 0};
    for (int i = 0; i < 30000; ++i) counts[r.below(3)]++;
    for (int c : counts) EXPECT_NEAR(c, 10000, 400);
}

TEST(StateHasher, DetectsOneUlpChangeAndFoldsNegativeZero) {
    StateHasher a, b, c, d;
    a.add(1.0f);
    b.add(std::nextafter(1.0f, 2.0f));
    EXPECT_NE(a.value(), b.value());
    c.add(0.0f);
    d.add(-0.0f);
    EXPECT_EQ(c.value(), d.value());
    EXPECT_EQ(StateHasher::toHex(0x0123456789abcdefULL), "0123456789abcdef");
}

TEST(FixedStepClock, CountsTicksAndClampsLongFrames) {
    FixedStepClock clock(0.01, 0.25);
    EXPECT_EQ(clock.advance(0.005), 0);
    EXPECT_EQ(clock.advance(0.006), 1);
    EXPECT_NEAR(clock.alpha(), 0.1, 1e-9);
    EXPECT_EQ(clock.advance(10.0), 25);  // a 10 s hitch runs 0.25 s worth of ticks, not 1000
}
