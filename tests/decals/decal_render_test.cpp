// The decals in the game, headless: looking down at the arena's floor, one shot, a look up and a
// second shot, back down; the capture after against the one before: the holes are darker pixels,
// nothing gets lighter; with the cap at 1 the first hole is recycled and only the second is left.
// A hole in a sunlit wall bends the normal: its rim lights up on the sun's side.
#include <gtest/gtest.h>

#include "core/image.h"
#include "run_process.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace obscura;
namespace fs = std::filesystem;

namespace {

const char* const kReplay = R"(obscura-replay 1
level media/levels/arena.map
seed 1
resolution 640 360
start 12 1.65 -6 -90 -80

3 capture before
5 button left down
6 button left up
10 mouse 0 -500
12 button left down
13 button left up
20 mouse 0 500
30 capture after
31 end
)";

struct Counts {
    int darker = 0, lighter = 0;
    int darkerNearCentre = 0;  // within 40 px of the crosshair (the first shot's hole)
};

Counts run(const fs::path& dir, int cap) {
    fs::create_directories(dir);
    std::ofstream(dir / "holes.replay") << kReplay;
    const std::string cmd = "cd " + std::string(OBSCURA_SOURCE_DIR) + " && XDG_CACHE_HOME=" + (dir / "cache").string() + " " +
                            OBSCURA_GAME + " --replay " + (dir / "holes.replay").string() + " --decals " +
                            std::to_string(cap) + " --capture-dir " + dir.string();
    const auto r = testing_support::runProcess(cmd);
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(r.out.find("decals: off"), std::string::npos) << r.out;
    const Image before = readPng((dir / "before.png").string()), after = readPng((dir / "after.png").string());
    Counts c;
    // The picture without the HUD (text at the top, ammo and bars at the bottom).
    for (int y = 50; y < 300; ++y)
        for (int x = 0; x < 640; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * 640 + x) * 4;
            const int d = (after.rgba[i] + after.rgba[i + 1] + after.rgba[i + 2]) - (before.rgba[i] + before.rgba[i + 1] + before.rgba[i + 2]);
            // Darker by 12 levels a channel and to under 0.6 of what was there: this floor lies in the
            // baked shade (about 26 of 255, engine_ext/lightbake), where a hole cannot take 40 levels.
            const int was = before.rgba[i] + before.rgba[i + 1] + before.rgba[i + 2];
            if (d < -3 * 12 && 10 * (was + d) < 6 * was) {
                ++c.darker;
                if (std::abs(x - 320) < 40 && std::abs(y - 180) < 40) ++c.darkerNearCentre;
            }
            if (d > 3 * 40) ++c.lighter;  // (small changes: the view returns to within a rounding of itself)
        }
    return c;
}

}  // namespace

TEST(DecalRender, HolesWhereTheRifleHitsAndTheCapRecycles) {
    const fs::path dir = fs::temp_directory_path() / ("obscura_decal_render_" + std::to_string(::getpid()));
    const Counts full = run(dir / "cap256", 256), one = run(dir / "cap1", 1);
    std::printf("[decals] darker pixels: cap 256: %d (%d by the crosshair), cap 1: %d (%d); lighter: %d, %d\n", full.darker,
                full.darkerNearCentre, one.darker, one.darkerNearCentre, full.lighter, one.lighter);
    EXPECT_GT(full.darkerNearCentre, 40);         // the first hole (~10 px across at 1.7 m)
    EXPECT_LT(one.darkerNearCentre, 5);           // recycled by the second
    EXPECT_GT(one.darker, 40);                    // the second hole is there
    EXPECT_GT(full.darker, one.darker + 30);      // both holes with room for 256
    EXPECT_LT(full.lighter + one.lighter, 10);    // decals only darken: nothing else moved
    fs::remove_all(dir);
}

// 0.4 m from the courtyard's south wall (its face looks north, towards the sun, 55 degrees up), fov
// 40: one shot at eye height. The hole is darker than the wall was. Its relief (the bent normal):
// the torn rim catches more light than the flat wall did (a decal that only changed the albedo could
// make nothing lighter), and inside the edge the crater's lower wall, which faces up towards the
// sun, is brighter than its upper wall, which faces down (the same grey paint all round: without
// the relief the two halves match).
TEST(DecalRender, AHoleInASunlitWallIsLitByItsBentNormal) {
    const fs::path dir = fs::temp_directory_path() / ("obscura_decal_relief_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "relief.replay") << R"(obscura-replay 1
level media/levels/arena.map
seed 1
resolution 640 360
start 34 1.65 -20.4 180 0
0 set fov 40
3 capture before
5 button left down
6 button left up
12 capture after
13 end
)";
    const std::string cmd = "cd " + std::string(OBSCURA_SOURCE_DIR) + " && XDG_CACHE_HOME=" + (dir / "cache").string() + " " +
                            OBSCURA_GAME + " --replay " + (dir / "relief.replay").string() + " --capture-dir " + dir.string();
    const auto r = testing_support::runProcess(cmd);
    ASSERT_EQ(r.code, 0) << r.out;
    const Image before = readPng((dir / "before.png").string()), after = readPng((dir / "after.png").string());
    auto sum = [](const Image& im, int x, int y) {
        const std::size_t i = (static_cast<std::size_t>(y) * 640 + x) * 4;
        return im.rgba[i] + im.rgba[i + 1] + im.rgba[i + 2];
    };
    int darker = 0, lighter = 0;
    double rowSum = 0;
    for (int y = 50; y < 300; ++y)
        for (int x = 0; x < 640; ++x) {
            const int d = sum(after, x, y) - sum(before, x, y);
            if (d < -3 * 40) ++darker, rowSum += y;
            if (d > 3 * 12) ++lighter;
        }
    ASSERT_GT(darker, 2000);  // the hole: ~70 px across at 0.4 m and fov 40
    const double middle = rowSum / darker;
    // The crater's paint: grey where the wall was red brick, not the black core, above and below
    // the middle.
    double upper = 0, lower = 0;
    int nUpper = 0, nLower = 0;
    for (int y = 50; y < 300; ++y)
        for (int x = 0; x < 640; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * 640 + x) * 4;
            const int r = after.rgba[i], g = after.rgba[i + 1], b = after.rgba[i + 2];
            const int br = before.rgba[i], bg = before.rgba[i + 1], bb = before.rgba[i + 2];
            const bool wasBrick = std::max({br, bg, bb}) - std::min({br, bg, bb}) > 40;
            if (!wasBrick || std::max({r, g, b}) - std::min({r, g, b}) > 25 || r + g + b < 3 * 25) continue;
            (y < middle ? upper : lower) += r + g + b;
            ++(y < middle ? nUpper : nLower);
        }
    upper /= std::max(nUpper, 1);
    lower /= std::max(nLower, 1);
    std::printf("[decals] relief: %d darker pixels, %d lighter; crater paint: upper half %.1f (%d px), lower %.1f (%d px)\n",
                darker, lighter, upper / 3, nUpper, lower / 3, nLower);
    EXPECT_GT(lighter, 200);            // the rim
    ASSERT_GT(std::min(nUpper, nLower), 200);
    EXPECT_GT(lower, upper * 1.15);     // the sunward wall of the crater at least 15 % brighter
    fs::remove_all(dir);
}

// A level whose decal_signs are mostly bad (tests/decals/levels/bad_signs.map) still loads and
// runs: one "decal_sign skipped" line a bad sign on stderr, the good ones drawn (the frame has the
// green "EXIT" sign's pixels where the player looks).
TEST(DecalRender, BadSignsAreSkippedAndTheLevelStillLoads) {
    const fs::path dir = fs::temp_directory_path() / ("obscura_decal_signs_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string shot = (dir / "signs.png").string();
    const std::string cmd = "cd " + std::string(OBSCURA_SOURCE_DIR) + " && XDG_CACHE_HOME=" + (dir / "cache").string() + " " +
                            OBSCURA_GAME + " --headless --ticks 3 --width 640 --height 360 --level tests/decals/levels/bad_signs.map" +
                            " --start-pose '5 1.65 -4 0 0' --screenshot " + shot + " 2>&1";
    const auto r = testing_support::runProcess(cmd);
    ASSERT_EQ(r.code, 0) << r.out;
    int skipped = 0;
    for (std::size_t at = 0; (at = r.out.find(": decal_sign skipped: ", at)) != std::string::npos; ++at) ++skipped;
    EXPECT_EQ(skipped, 14) << r.out;  // every bad sign in the file, no good one
    const Image im = readPng(shot);
    int green = 0;  // the sign's _color "0 200 50" under the room's light
    for (std::size_t i = 0; i + 3 < im.rgba.size(); i += 4)
        if (im.rgba[i + 1] > 60 && im.rgba[i + 1] > 2 * im.rgba[i] && im.rgba[i + 1] > 2 * im.rgba[i + 2]) ++green;
    EXPECT_GT(green, 100) << shot;
    fs::remove_all(dir);
}
