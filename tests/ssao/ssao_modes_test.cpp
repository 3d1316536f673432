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
