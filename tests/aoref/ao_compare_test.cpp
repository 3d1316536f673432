#include <gtest/gtest.h>

#include "aoref/ao_compare.h"

#include <cmath>
#include <stdexcept>

using namespace obscura::aoref;

namespace {
// A 4-pixel frame: one sky pixel (reference 1, not hit), one open pixel (0.99), two occluded
// (0.5 and 0.8, below the 0.95 threshold).
const std::vector<float> kRef = {1.0f, 0.99f, 0.5f, 0.8f};
const std::vector<std::uint8_t> kHit = {0, 1, 1, 1};
}  // namespace

TEST(AoCompare, OffIsScoredOnTheOccludedRegionByHowDarkTheTruthIs) {
    const AoError off = compareAo(kRef, kHit, whiteAo(kRef.size()));
    EXPECT_EQ(off.pixels, 3);
    EXPECT_EQ(off.occludedPixels, 2);
    EXPECT_NEAR(off.occludedShare(), 2.0 / 3.0, 1e-12);
    // Whole frame: (0.01 + 0.5 + 0.2) / 3; the sky pixel counts nowhere.
    EXPECT_NEAR(off.mae, 0.71 / 3, 1e-6);
    EXPECT_NEAR(off.bias, 0.71 / 3, 1e-6);  // all too light
    // Occluded region: (0.5 + 0.2) / 2.
    EXPECT_NEAR(off.occludedMae, 0.35, 1e-6);
    EXPECT_NEAR(off.occludedBias, 0.35, 1e-6);
}

TEST(AoCompare, OccludedRegionSeparatesModesTheWholeFrameBarelyTellsApart) {
    // 100 pixels, 95 open (reference 1) and 5 occluded (0.4). A mode that darkens the occluded
    // pixels right but greys the open ones slightly against off: whole-frame MAE close, occluded
    // MAE far apart.
    std::vector<float> ref(100, 1.0f), mode(100, 0.97f);
    for (int i = 0; i < 5; ++i) ref[i] = mode[i] = 0.4f;
    const std::vector<std::uint8_t> hit(100, 1);
    const AoError off = compareAo(ref, hit, whiteAo(100));
    const AoError m = compareAo(ref, hit, mode);
    EXPECT_NEAR(off.mae, 0.03, 1e-6);
    EXPECT_NEAR(m.mae, 0.95 * 0.03, 1e-6);
    EXPECT_NEAR(off.occludedMae, 0.6, 1e-6);
    EXPECT_NEAR(m.occludedMae, 0.0, 1e-6);
    EXPECT_NEAR(m.bias, -0.95 * 0.03, 1e-6);  // too dark on the open floor
}

TEST(AoCompare, SignedBiasAndRmse) {
    const std::vector<float> mode = {0.0f, 0.99f, 0.7f, 0.6f};  // +0.2 and -0.2 on the occluded pixels
    const AoError e = compareAo(kRef, kHit, mode);
    EXPECT_NEAR(e.occludedMae, 0.2, 1e-6);
    EXPECT_NEAR(e.occludedBias, 0.0, 1e-6);
    EXPECT_NEAR(e.rmse, std::sqrt(0.08 / 3), 1e-6);
}

TEST(AoCompare, ThresholdIsStrictAndConfigurable) {
    const std::vector<float> ref = {0.95f, 0.9f};
    const std::vector<std::uint8_t> hit = {1, 1};
    EXPECT_EQ(compareAo(ref, hit, whiteAo(2)).occludedPixels, 1);  // 0.95 itself is not occluded
    EXPECT_EQ(compareAo(ref, hit, whiteAo(2), 0.85).occludedPixels, 0);
}

TEST(AoCompare, NothingOccludedGivesZeroNotNan) {
    const AoError e = compareAo({1.0f, 1.0f}, {1, 1}, whiteAo(2));
    EXPECT_EQ(e.occludedPixels, 0);
    EXPECT_EQ(e.occludedMae, 0.0);
    EXPECT_EQ(e.occludedShare(), 0.0);
    const AoError none = compareAo({}, {}, {});
    EXPECT_EQ(none.pixels, 0);
    EXPECT_EQ(none.occludedShare(), 0.0);
}

TEST(AoCompare, SizesMustMatch) {
    EXPECT_THROW(compareAo(kRef, kHit, whiteAo(3)), std::invalid_argument);
    EXPECT_THROW(compareAo(kRef, {1, 1}, whiteAo(4)), std::invalid_argument);
}

TEST(AoCompare, Rgba8RedChannelAndFormat) {
    const auto ao = aoFromRgba8({255, 0, 0, 255, 51, 9, 9, 255});
    ASSERT_EQ(ao.size(), 2u);
    EXPECT_FLOAT_EQ(ao[0], 1.0f);
    EXPECT_FLOAT_EQ(ao[1], 0.2f);
    const AoError e = compareAo(kRef, kHit, whiteAo(4));
    const std::string line = formatAoError(e);
    EXPECT_NE(line.find("occluded_mae=0.35000"), std::string::npos) << line;
    EXPECT_NE(line.find("occluded_pixels=2 "), std::string::npos) << line;
    EXPECT_NE(line.find("pixels=3 "), std::string::npos) << line;
}

TEST(AoCompare, BoxAverageIsEachBlocksMean) {
    // 4 x 2 in 2 x 2 blocks: the left block 0, 1, 0.5, 0.5; the right block all 0.2.
    const std::vector<float> img = {0.0f, 1.0f, 0.2f, 0.2f,  //
                                    0.5f, 0.5f, 0.2f, 0.2f};
    const std::vector<float> avg = boxAverage(img, 4, 2, 2);
    ASSERT_EQ(avg.size(), 2u);
    EXPECT_NEAR(avg[0], 0.5f, 1e-6);
    EXPECT_NEAR(avg[1], 0.2f, 1e-6);
    EXPECT_EQ(boxAverage(img, 4, 2, 1), img);
    EXPECT_THROW(boxAverage(img, 4, 2, 3), std::invalid_argument);
    EXPECT_THROW(boxAverage(img, 2, 2, 2), std::invalid_argument);
}
