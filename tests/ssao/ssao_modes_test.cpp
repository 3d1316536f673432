#include <gtest/gtest.h>

#include "ssao/ssao_modes.h"

using namespace obscura::ssao;

TEST(SsaoModes, CycleForwardAndBackWraps) {
    const auto& m = modeNames();
    ASSERT_GE(m.size(), 3u);
    EXPECT_EQ(m.front(), "off");
    std::string mode = "off";
    for (std::size_t i = 0; i < m.size(); ++i) mode = cycleMode(mode, +1);
    EXPECT_EQ(mode, "off");  // a full turn comes back
    EXPECT_EQ(cycleMode("off", -1), m.back());
    EXPECT_EQ(cycleMode(m[1], -1), "off");
    EXPECT_EQ(cycleMode("nonsense", +1), m[1]);
    EXPECT_TRUE(isMode("hemisphere"));
    EXPECT_TRUE(isMode("heightfield"));
    EXPECT_TRUE(isMode("gtao"));
    EXPECT_EQ(cycleMode("heightfield", +1), "gtao");  // O reaches gtao last, then wraps to off
    EXPECT_FALSE(isMode("Hemisphere"));
    EXPECT_EQ(m.back(), "combined");  // appended: the cycle's older order is kept
}

TEST(SsaoModes, TheHeightMapModesAreNamed) {
    EXPECT_TRUE(readsHeightMap("heightfield"));
    EXPECT_TRUE(readsHeightMap("combined"));
    EXPECT_FALSE(readsHeightMap("horizon"));
    EXPECT_FALSE(readsHeightMap("off"));
}

TEST(SsaoModes, TheTruthKeyTracesTheRadiusTheModeEstimates) {
    // combined answers to its large radius (V_small(0..r) x V_large(r..R) is the truth at R)...
    EXPECT_DOUBLE_EQ(truthRadius("combined", 0.6, 2.0), 2.0);
    // ...and to the small one when the large does not reach past it (its small term alone).
    EXPECT_DOUBLE_EQ(truthRadius("combined", 0.6, 0.6), 0.6);
    EXPECT_DOUBLE_EQ(truthRadius("combined", 1.0, 0.5), 1.0);
    for (const char* mode : {"off", "horizon", "gtao", "heightfield"}) EXPECT_DOUBLE_EQ(truthRadius(mode, 0.6, 2.0), 0.6);
}
