#include <gtest/gtest.h>

#include "ao_truth/truth_compare.h"

using namespace obscura;
using namespace obscura::ao_truth;

namespace {
// 4 pixels: sky, open (0.99), two occluded (0.5, 0.8); as tests/aoref's fixture.
ssao::AoImage reference() {
    ssao::AoImage r;
    r.width = 2;
    r.height = 2;
    r.ao = {1.0f, 0.99f, 0.5f, 0.8f};
    r.hit = {0, 1, 1, 1};
    return r;
}
}  // namespace

TEST(TruthShow, CycleAndNames) {
    EXPECT_EQ(nextShow(Show::Off), Show::Reference);
    EXPECT_EQ(nextShow(Show::Reference), Show::Mode);
    EXPECT_EQ(nextShow(Show::Mode), Show::HeatMap);
    EXPECT_EQ(nextShow(Show::HeatMap), Show::Off);
    for (const auto& n : showNames()) EXPECT_EQ(showName(*showFromName(n)), n);
    EXPECT_FALSE(showFromName("heat-map"));
    EXPECT_FALSE(showFromName(""));
}

TEST(TruthScore, ModeAndOffAgainstAHandMadeReference) {
    // The mode: right on the open pixel, 0.1 too dark on 0.5, 0.2 too light on 0.8.
    const Score s = score(reference(), {0.3f, 0.99f, 0.4f, 1.0f});
    EXPECT_EQ(s.mode.pixels, 3);  // the sky pixel counts nowhere
    EXPECT_NEAR(s.mode.mae, 0.3 / 3, 1e-6);
    EXPECT_EQ(s.mode.occludedPixels, 2);
    EXPECT_NEAR(s.mode.occludedMae, 0.15, 1e-6);
    EXPECT_NEAR(s.mode.occludedBias, 0.05, 1e-6);
    // off: white everywhere.
    EXPECT_NEAR(s.off.mae, 0.71 / 3, 1e-6);
    EXPECT_NEAR(s.off.occludedMae, 0.35, 1e-6);
}

TEST(TruthHeatMap, DarkerLighterEqualAndSky) {
    // Darker than the truth: blue; lighter: orange; equal: black; full colour from kHeatFullScale.
    const auto darker = heatColour(-kHeatFullScale), lighter = heatColour(kHeatFullScale), same = heatColour(0);
    EXPECT_GT(darker[2], 250);
    EXPECT_LT(darker[0], 30);
    EXPECT_GT(lighter[0], 250);
    EXPECT_LT(lighter[2], 5);
    EXPECT_EQ(same, (std::array<std::uint8_t, 4>{0, 0, 0, 255}));
    EXPECT_EQ(heatColour(-1.0), darker);  // saturates
    const auto half = heatColour(kHeatFullScale / 2);
    EXPECT_NEAR(half[0], 128, 1);  // linear in |error|
    const auto img = heatMapRgba(reference(), {0.0f, 0.99f, 0.0f, 1.0f});
    ASSERT_EQ(img.size(), 16u);
    EXPECT_EQ((std::array<std::uint8_t, 4>{img[0], img[1], img[2], img[3]}), kHeatSky);
    EXPECT_EQ(img[4], 0);   // equal: black
    EXPECT_GT(img[10], 250);  // 0.5 too dark: full blue
    EXPECT_GT(img[12], 100);  // 0.2 too light: orange, 0.4 of full
    EXPECT_LT(img[12], 110);
    EXPECT_EQ(img[14], 0);
}

TEST(TruthCompare, ResampleNearestIsTheIdentityAtTheSameSizeAndPicksCentres) {
    const std::vector<float> src = {0, 1, 2, 3, 4, 5};  // 3 x 2
    EXPECT_EQ(resampleNearest(src, 3, 2, 3, 2), src);
    EXPECT_EQ(resampleNearest(src, 3, 2, 6, 4), (std::vector<float>{0, 0, 1, 1, 2, 2, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 3, 3, 4, 4, 5, 5}));
    EXPECT_EQ(resampleNearest({0, 1, 2, 3}, 4, 1, 2, 1), (std::vector<float>{1, 3}));
}

TEST(TruthHud, LinesSayWhatIsShownTheProgressAndTheScores) {
    HudFacts f;
    EXPECT_TRUE(hudLines(f).empty());  // off: nothing
    f.show = Show::Reference;
    f.mode = "horizon";
    f.width = 80;
    f.height = 45;
    f.rays = 64;
    f.totalRays = 256;
    auto lines = hudLines(f);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0], "truth (T): reference 80x45 64/256 rays");
    Score s = score(reference(), {0.3f, 0.99f, 0.4f, 1.0f});
    s.rays = 64;  // scored against the 64-ray reference: said so
    f.score = &s;
    lines = hudLines(f);
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[1], "horizon: error 0.100 (vs 64 rays)");
    EXPECT_EQ(lines[2], " occluded: error 0.150, too light 0.050");
    s.rays = 256;
    f.rays = 256;
    f.show = Show::HeatMap;
    lines = hudLines(f);
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[0], "truth (T): heat map 80x45 256 rays");
    EXPECT_EQ(lines[1], "horizon: error 0.100");
    EXPECT_EQ(lines[2], " occluded: error 0.150, too light 0.050");
    EXPECT_EQ(lines[3], "off: error 0.237, occluded (67%) 0.350");
    EXPECT_EQ(lines[4], "heat: mode - truth, black 0,");
    EXPECT_EQ(lines[5], "blue -0.5 (darker), orange +0.5");
    for (const auto& l : lines) EXPECT_LE(l.size(), 44u) << l;  // fits a 320 x 180 capture's HUD
    f.mode = "off";  // the mode is off: its line is off's
    lines = hudLines(f);
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[1], "off: error 0.237, occluded (67%) 0.350");
}
