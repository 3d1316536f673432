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
