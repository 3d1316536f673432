// End-to-end runs of the real game executable, headless under the Xvfb the suite runs in:
// a screenshot that shows the level, repeatable state hashes, and clear errors for bad input.
#include <gtest/gtest.h>

#include "core/image.h"
#include "run_process.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace fs = std::filesystem;

namespace {
using GameRun = obscura::testing_support::ProcessResult;

GameRun game(const std::string& args, const std::string& env = "") {
    return obscura::testing_support::runProcess(env + " '" OBSCURA_GAME "' " + args);
}

std::string temp(const std::string& name) { return (fs::path(testing::TempDir()) / name).string(); }

std::string stateHash(const std::string& out) {
    const auto at = out.find("state-hash ");
    return at == std::string::npos ? "" : out.substr(at + 11, 16);
}
}  // namespace

TEST(Headless, RunsTheDefaultLevelAndItsScreenshotShowsIt) {
    const std::string shot = temp("headless120.png");
    fs::remove(shot);
    const GameRun r = game("--headless --ticks 120 --width 320 --height 180 --screenshot " + shot);
    ASSERT_EQ(r.code, 0) << r.out;
    const obscura::Image im = obscura::readPng(shot);
    ASSERT_EQ(im.width, 320);
    ASSERT_EQ(im.height, 180);
    // Not blank: many distinct colours and real contrast across the frame.
    std::set<std::uint32_t> colours;
    double sum = 0, sum2 = 0;
    for (std::size_t i = 0; i < im.rgba.size(); i += 4) {
        colours.insert(im.rgba[i] << 16 | im.rgba[i + 1] << 8 | im.rgba[i + 2]);
        const double l = 0.2126 * im.rgba[i] + 0.7152 * im.rgba[i + 1] + 0.0722 * im.rgba[i + 2];
        sum += l;
        sum2 += l * l;
    }
    const double n = im.rgba.size() / 4.0, mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
    EXPECT_GT(colours.size(), 500u);
    EXPECT_GT(sd, 15.0);
    EXPECT_GT(mean, 30.0);   // lit, not black
    EXPECT_LT(mean, 230.0);  // not blown out
    EXPECT_EQ(stateHash(r.out).size(), 16u) << r.out;
}

TEST(Headless, TwoRunsPrintTheSameStateHash) {
    const GameRun a = game("--headless --ticks 90 --width 64 --height 64");
    const GameRun b = game("--headless --ticks 90 --width 64 --height 64");
    ASSERT_EQ(a.code, 0) << a.out;
    ASSERT_EQ(b.code, 0) << b.out;
    EXPECT_EQ(stateHash(a.out), stateHash(b.out));
    const GameRun c = game("--headless --ticks 91 --width 64 --height 64");
    EXPECT_NE(stateHash(a.out), stateHash(c.out));  // the hash does follow the simulation
}

TEST(Headless, MalformedMapNamesFileLineAndColumn) {
    const std::string map = temp("broken.map");
    std::ofstream(map) << "{\n\"classname\" \"worldspawn\"\n{\n( 0 0 0 ) ( 0 1 0 ( 1 0 0 ) tex 0 0 0 1 1\n}\n}\n";
    const GameRun r = game("--headless --ticks 1 --level " + map);
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.out.find(map + ":4:19: expected ')'"), std::string::npos) << r.out;
}

TEST(Headless, MissingLevelAndMissingMeshAreClearErrors) {
    GameRun r = game("--headless --ticks 1 --level /nonexistent/level.map");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.out.find("/nonexistent/level.map: cannot open map file"), std::string::npos) << r.out;

    const std::string map = temp("model.map");
    std::ofstream(map) << "{\n\"classname\" \"worldspawn\"\n}\n{\n\"classname\" \"misc_model\"\n\"origin\" \"0 0 0\"\n\"model\" \"nothere.mesh\"\n}\n";
    r = game("--headless --ticks 1 --level " + map);
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.out.find("misc_model 'model' 'nothere.mesh' not found"), std::string::npos) << r.out;
}

TEST(Headless, UnknownOptionAndBadConfigExitWithUsageErrors) {
    GameRun r = game("--frobnicate");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.out.find("command line"), std::string::npos) << r.out;
    const std::string cfg = temp("bad.cfg");
    std::ofstream(cfg) << "width = 640\nfov = wide\n";
    r = game("--headless --config " + cfg);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.out.find(cfg + ":2: setting 'fov': 'wide' is not a number"), std::string::npos) << r.out;
}

TEST(Headless, NoDisplayIsAClearErrorNotACrashOrHang) {
    const GameRun r = game("--headless --ticks 1", "env -u DISPLAY");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.out.find("cannot open an X display"), std::string::npos) << r.out;
}

TEST(Headless, HelpListsTheOptions) {
    const GameRun r = game("--help");
    EXPECT_EQ(r.code, 0);
    for (const char* o : {"--level", "--width", "--fullscreen", "--vsync", "--fov", "--mouse-sensitivity", "--invert-mouse",
                          "--bind-forward", "--headless", "--ticks", "--screenshot", "--replay", "--timedemo"})
        EXPECT_NE(r.out.find(o), std::string::npos) << o;
}

TEST(Headless, MiscModelLoadsAMeshWithFallbackMaterials) {
    const fs::path mesh = fs::path(OBSCURA_THIRD_PARTY_DIR) / "scenes/sibenik.mesh";
    const std::string map = temp("sibenik.map");
    std::ofstream(map) << "{\n\"classname\" \"worldspawn\"\n}\n{\n\"classname\" \"info_player_start\"\n\"origin\" \"0 0 400\"\n}\n"
                       << "{\n\"classname\" \"misc_model\"\n\"origin\" \"0 0 0\"\n\"model\" \"" << mesh.string() << "\"\n}\n";
    const GameRun r = game("--headless --ticks 30 --width 64 --height 64 --level " + map);
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("1 models, 18 generated materials"), std::string::npos) << r.out;  // sibenik/* are not shipped
}

TEST(Headless, NoAudioDeviceRunsSilentWithOneWarning) {
    // OpenAL Soft with no backend at all (CI has no sound card either): the game runs, silent,
    // after one line saying so.
    const GameRun r = game("--headless --ticks 30 --width 64 --height 64 2>&1", "ALSOFT_DRIVERS=no_such_backend");
    ASSERT_EQ(r.code, 0) << r.out;
    std::size_t lines = 0;
    for (std::size_t at = r.out.find("audio:"); at != std::string::npos; at = r.out.find("audio:", at + 1)) ++lines;
    EXPECT_EQ(lines, 1u) << r.out;
    EXPECT_NE(r.out.find("running silent"), std::string::npos) << r.out;
}

// Ctrl-C and SIGTERM end every run mode within a second, through the normal shutdown: the run
// leaves its frame loop, prints its state hash and exits 0.
namespace {
struct Stopped {
    int code = -1;
    long ms = -1;  // from the signal to the exit
    std::string out;
};

Stopped stopAfter(const std::string& args, const char* signal, int afterSeconds) {
    const std::string log = temp(std::string("stopped-") + signal + ".log");
    const GameRun r = obscura::testing_support::runProcess(
        "'" OBSCURA_GAME "' " + args + " > '" + log + "' 2>&1 & pid=$!; sleep " + std::to_string(afterSeconds) +
        "; t0=$(date +%s%N); kill -" + signal + " $pid; wait $pid; rc=$?; t1=$(date +%s%N); "
        "echo \"rc=$rc ms=$(( (t1 - t0) / 1000000 ))\"; cat '" + log + "'");
    Stopped s;
    s.out = r.out;
    std::sscanf(r.out.c_str(), "rc=%d ms=%ld", &s.code, &s.ms);
    return s;
}
}  // namespace

TEST(Headless, SigtermAndCtrlCEndEveryRunModeCleanlyWithinASecond) {
    const std::string dir = temp("stopped-captures");
    fs::create_directories(dir);
    const std::string timedemo = std::string(OBSCURA_SOURCE_DIR) + "/bench/timedemo_arena.replay";
    struct Mode {
        std::string args;
        const char* signal;
    };
    for (const Mode& m : {Mode{"--headless --ticks 100000000 --width 64 --height 64", "TERM"},
                          Mode{"--headless --ticks 100000000 --width 64 --height 64", "INT"},
                          Mode{"--replay " + timedemo + " --capture-dir " + dir, "TERM"},
                          Mode{"--headless --timedemo " + timedemo, "INT"}}) {
        const Stopped s = stopAfter(m.args, m.signal, 4);
        EXPECT_EQ(s.code, 0) << m.args << "\n" << s.out;
        EXPECT_GE(s.ms, 0) << s.out;
        EXPECT_LT(s.ms, 1000) << m.args << "\n" << s.out;
        EXPECT_NE(s.out.find(std::string("stopped by SIG") + m.signal), std::string::npos) << s.out;
        EXPECT_EQ(stateHash(s.out).size(), 16u) << s.out;
    }
}
