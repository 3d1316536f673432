// The smoke's march in the real game, headless: the level's sun shadow map reaches the cloud.
// Level: tests/smoke/levels/sun_tower.map (tools/levelgen/make_smoke_levels.py): a 40 m tower west
// of the cloud's 16 m box shadows the box's north half (the game's z < 0, the right of this view)
// from the sun; the solver's own transmittance towards the sun cannot see it (outside its grid).
#include <gtest/gtest.h>

#include "core/image.h"
#include "run_process.h"

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using obscura::testing_support::ProcessResult;

namespace {
const std::string kLevel = std::string(OBSCURA_SOURCE_DIR) + "/tests/smoke/levels/sun_tower.map";

// 12 m east of a cloud released at the origin, facing west (yaw 90) and a little down on it, 12 s
// after the release (360 ticks): a dome about 5 m wide, lying across the shadow's edge (z = 0, the
// middle column).
obscura::Image shoot(const std::string& name, const std::string& extra) {
    const std::string png = (fs::path(testing::TempDir()) / ("smoke_render_" + name + ".png")).string();
    const ProcessResult r = obscura::testing_support::runProcess(
        std::string("'" OBSCURA_GAME "' --headless --ticks 360 --width 320 --height 180 --hud off --ssao off --level '") +
        kLevel + "' --start-pose '12 1.7 0 90 10' " + extra + " --screenshot " + png);
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(r.out.find("stage ("), std::string::npos) << "a stage of the frame turned off:\n" << r.out;
    return obscura::readPng(png);
}

// Mean Rec. 709 luma (gamma-encoded, 0..255) of the window [x0, x1) x [y0, y1), in fractions of the picture.
double luma(const obscura::Image& im, double x0, double x1, double y0, double y1) {
    double sum = 0;
    int n = 0;
    for (int y = static_cast<int>(y0 * im.height); y < static_cast<int>(y1 * im.height); ++y)
        for (int x = static_cast<int>(x0 * im.width); x < static_cast<int>(x1 * im.width); ++x) {
            const std::uint8_t* p = &im.rgba[(static_cast<std::size_t>(y) * im.width + x) * 4];
            sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            ++n;
        }
    return sum / n;
}

// Two windows on the dome's thick middle, either side of the shadow's edge: west of the camera's
// right is north (shadowed), its left south (in the sun).
constexpr double kRows[2] = {0.58, 0.73};
constexpr double kLit[2] = {0.40, 0.475}, kShadowed[2] = {0.525, 0.60};
}  // namespace

// Before the march read the shadow map the two windows were alike (luma 164.6 sunlit, 164.4
// shadowed, main at 319005e): the solver's transmittance alone lit both halves the same. With it:
// 164.6 and 129.9 (0.79 in these gamma-encoded values, about 0.59 in linear light: the sky's
// ambient is what the shadowed half keeps). The bound, 0.9, is halfway between.
TEST(SmokeRender, ATowerOutsideTheBoxShadowsItsHalfOfTheCloud) {
    const obscura::Image cloud = shoot("cloud", "--smoke-at '0 0.5 0'");
    const obscura::Image bare = shoot("bare", "");
    const double lit = luma(cloud, kLit[0], kLit[1], kRows[0], kRows[1]);
    const double shadowed = luma(cloud, kShadowed[0], kShadowed[1], kRows[0], kRows[1]);
    // The windows are on the cloud: without it they show the floor, in and out of the tower's
    // shadow, and the cloud changes both.
    const double litFloor = luma(bare, kLit[0], kLit[1], kRows[0], kRows[1]);
    const double shadowedFloor = luma(bare, kShadowed[0], kShadowed[1], kRows[0], kRows[1]);
    EXPECT_GT(std::abs(lit - litFloor), 15.0) << "no cloud in the sunlit window";
    EXPECT_GT(std::abs(shadowed - shadowedFloor), 15.0) << "no cloud in the shadowed window";
    EXPECT_LT(shadowed, 0.9 * lit) << "the tower's shadow does not darken the cloud: lit " << lit << ", shadowed " << shadowed;
}
