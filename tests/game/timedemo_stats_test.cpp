#include <gtest/gtest.h>

#include "timedemo_stats.h"

using namespace obscura;

TEST(TimedemoStats, PercentilesByNearestRank) {
    std::vector<double> ms;
    for (int i = 100; i >= 1; --i) ms.push_back(i);  // 1..100 ms, unsorted
    const FrameStats s = computeFrameStats(ms);
    EXPECT_EQ(s.frames, 100u);
    EXPECT_DOUBLE_EQ(s.seconds, 5.05);
    EXPECT_DOUBLE_EQ(s.meanMs, 50.5);
    EXPECT_DOUBLE_EQ(s.medianMs, 50.5);
    EXPECT_DOUBLE_EQ(s.p95Ms, 95);
    EXPECT_DOUBLE_EQ(s.p99Ms, 99);
    EXPECT_DOUBLE_EQ(s.maxMs, 100);
}

TEST(TimedemoStats, OddCountMedianAndEmptyInput) {
    EXPECT_DOUBLE_EQ(computeFrameStats({3, 1, 2}).medianMs, 2);
    EXPECT_EQ(computeFrameStats({}).frames, 0u);
}

TEST(TimedemoStats, MachineReadableLine) {
    const std::string text = formatFrameStats(computeFrameStats({10, 20}), "demo");
    EXPECT_NE(text.find("timedemo name=demo frames=2 seconds=0.0300"), std::string::npos) << text;
    EXPECT_NE(text.find("mean_ms=15.0000"), std::string::npos) << text;
}
