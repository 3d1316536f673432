// The volumetrics' reuse of the frame before (shaders/frame/volume_resolve.frag: a quarter of the
// pixels marched a frame, the rest reprojected and clamped to the new samples) where reuse goes
// wrong: a 90-degree turn in one tick (the old view's cloud must not stay on screen as a ghost)
// and a camera walking into a cloud (it must see the cloud at once, not the clear air it came
// from). Each compares the volume buffer as the frame left it (--volume-dump without a capture)
// with the same state drawn until every pixel was marched on it (a capture settles it: the
// dump follows the screenshot), against the difference the effect would make if it failed.
#include <gtest/gtest.h>

#include "core/pfm.h"
#include "run_process.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace fs = std::filesystem;

namespace {

// The arena's courtyard cloud (as smoke_tunnel_side.replay): released at tick 0 in front of the
// player, who faces it; about 4 m across by tick 200. 160 x 90: the volume buffer is 80 x 45.
std::string script(const std::string& commands, int last) {
    return "obscura-replay 1\nlevel media/levels/arena.map\nseed 1\nresolution 160 90\n0 mouse 4000 -200\n"
           "0 set smoke-at 31 0.3 -30\n" + commands + std::to_string(last) + " end\n";
}

// The volume buffer at the replay's end: as the last frame left it, or settled (see above).
obscura::FloatImage volumeAtEnd(const std::string& name, const std::string& replay, bool settled) {
    const fs::path dir = fs::path(testing::TempDir()) / ("volume_history_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "run.replay") << replay;
    const std::string pfm = (dir / "volume.pfm").string();
    const auto r = obscura::testing_support::runProcess(std::string("'" OBSCURA_GAME "' --replay '") + (dir / "run.replay").string() +
                                                        "' --capture-dir '" + dir.string() + "' --volume-dump '" + pfm + "'" +
                                                        (settled ? " --screenshot '" + (dir / "end.png").string() + "'" : ""));
    EXPECT_EQ(r.code, 0) << r.out;
    return obscura::readPfm(pfm);
}

double meanAbsDifference(const obscura::FloatImage& a, const obscura::FloatImage& b) {
    EXPECT_EQ(a.rgb.size(), b.rgb.size());
    double sum = 0;
    for (std::size_t i = 0; i < a.rgb.size() && i < b.rgb.size(); ++i) sum += std::fabs(a.rgb[i] - b.rgb[i]);
    return a.rgb.empty() ? 0 : sum / static_cast<double>(a.rgb.size());
}

// Tick 200, facing the cloud, settled: the view before the turn, and outside the cloud before the walk.
const obscura::FloatImage& facingTheCloud() {
    static const obscura::FloatImage v = volumeAtEnd("facing", script("", 200), true);
    return v;
}

// A replay's end twice, as the frame left the buffer and settled: how far apart they are (what
// reuse left behind), how far the settled buffer is from the view facing the cloud (the
// difference a failure would make), and the settled buffer's mean light (is the cloud in view).
struct Reuse {
    double left = 0, whole = 0, light = 0;
};
Reuse reuseAtEnd(const std::string& name, const std::string& replay) {
    const obscura::FloatImage raw = volumeAtEnd(name + "_raw", replay, false), settled = volumeAtEnd(name + "_settled", replay, true);
    Reuse r{meanAbsDifference(raw, settled), meanAbsDifference(facingTheCloud(), settled), 0};
    for (float v : settled.rgb) r.light += v;
    if (!settled.rgb.empty()) r.light /= static_cast<double>(settled.rgb.size());
    return r;
}

}  // namespace

TEST(VolumeHistory, ANinetyDegreeTurnInOneTickLeavesNoGhost) {
    const Reuse r = reuseAtEnd("turn", script("200 mouse 4091 0\n", 200));  // 90 degrees right, before tick 200's step
    std::cout << "after the turn, the frame's volume buffer against the settled one: " << r.left
              << " mean |light| apart; the view before the turn against it: " << r.whole << "\n";
    ASSERT_GT(r.whole, 0.02) << "the cloud is not in the view before the turn: nothing to leave a ghost";
    EXPECT_LT(r.left, 0.05 * r.whole) << "the old view's light stays in the buffer";
}

// Half the turn: the cloud's box stays in the view (a cloud out of view is not marched at all:
// SmokeRender::cull), so what the turn leaves is the reprojection's and the clamp's work.
TEST(VolumeHistory, AFortyFiveDegreeTurnKeepsTheCloudAndLeavesNoGhost) {
    const Reuse r = reuseAtEnd("turn45", script("200 mouse 2045 0\n", 200));
    std::cout << "after a 45-degree turn: " << r.left << " mean |light| apart from the settled buffer; the view before: "
              << r.whole << "; the settled buffer's mean light " << r.light << "\n";
    ASSERT_GT(r.light, 0.01) << "the cloud left the view: the turn tests nothing";
    ASSERT_GT(r.whole, 0.02);
    EXPECT_LT(r.left, 0.05 * r.whole) << "the old view's light stays in the buffer";
}

TEST(VolumeHistory, ACameraWalkingIntoACloudSeesItAtOnce) {
    const Reuse r = reuseAtEnd("walk", script("200 key lshift down\n200 key w down\n", 235));  // 35 ticks of sprint: inside
    std::cout << "inside the cloud, the frame's volume buffer against the settled one: " << r.left
              << " mean |light| apart; the view from outside against it: " << r.whole << "\n";
    ASSERT_GT(r.whole, 0.02) << "the walk did not change the view's smoke: not inside the cloud";
    EXPECT_LT(r.left, 0.05 * r.whole) << "the buffer still shows the air the camera came from";
}
