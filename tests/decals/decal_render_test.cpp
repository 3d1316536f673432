// The decals in the game, headless: looking down at the arena's floor, one shot, a look up and a
// second shot, back down; the capture after against the one before: the holes are darker pixels,
// nothing gets lighter; with the cap at 1 the first hole is recycled and only the second is left.
#include <gtest/gtest.h>

#include "core/image.h"
#include "run_process.h"

#include <unistd.h>

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
            if (d < -3 * 40) {
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
