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

TEST(TimedemoStats, SegmentsLeaveOutWarmupAndCompareWithTheFirst) {
    std::vector<TimedemoSegment> segs = {{"start", {100, 10, 10, 10}, {90, 20, 20, 20}},
                                         {"ssao=horizon", {500, 30, 34}, {400, 50, 60}}};
    const std::string text = formatSegments(segs, 1);
    // The 100 and 500 ms warm-up frames are left out: means 10 and 32, so +22 against the first.
    EXPECT_NE(text.find("label=\"ssao=horizon\" frames=2 mean_ms=32.0000"), std::string::npos) << text;
    EXPECT_NE(text.find("added_ms=22.0000 cpu_ms=55.0000 added_cpu_ms=35.0000"), std::string::npos) << text;
    EXPECT_NE(text.find("label=\"start\" frames=3 mean_ms=10.0000"), std::string::npos) << text;
    EXPECT_EQ(formatSegments({segs[0]}, 1), "");
}
