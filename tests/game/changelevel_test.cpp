// trigger_changelevel end to end (game/app/game_app_level.cpp): the playtest replay plays from its
// start to its exit and ends there; a headless run that touches one loads the next map from beside
// the level; a next map that is missing or not a bare name ends the run with a line saying why.
#include <gtest/gtest.h>

#include "../map/test_maps.h"
#include "run_process.h"

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using obscura::map::testdata::cube;

namespace {
const std::string kLevels = std::string(OBSCURA_SOURCE_DIR) + "/tests/sim/levels";

obscura::testing_support::ProcessResult game(const std::string& args) {
    return obscura::testing_support::runProcess("'" OBSCURA_GAME "' --width 160 --height 90 " + args);
}

// A room whose player start stands in a trigger_changelevel naming `next`.
std::string roomWithExit(const std::string& file, const std::string& next) {
    const std::string path = (fs::path(testing::TempDir()) / file).string();
    std::ofstream(path) << "{\n\"classname\" \"worldspawn\"\n" << cube(-256, -256, -512, "floor", 512) << "}\n"
                        << "{\n\"classname\" \"info_player_start\"\n\"origin\" \"0 0 24\"\n}\n"
                        << "{\n\"classname\" \"trigger_changelevel\"\n\"map\" \"" << next << "\"\n" << cube(-64, -64, 0, "trigger", 128) << "}\n";
    return path;
}
}  // namespace

TEST(Changelevel, ThePlaytestReplayPlaysFromItsStartToItsExit) {
    const auto r = game("--replay " OBSCURA_SOURCE_DIR "/tests/replay/scripts/playtest.replay --replay-draw captures --capture-dir " +
                        (fs::path(testing::TempDir()) / "playtest_caps").string());
    ASSERT_EQ(r.code, 0) << r.out;
    const auto at = r.out.find("changelevel playtest_end at tick ");
    ASSERT_NE(at, std::string::npos) << r.out;
    const std::string tick = r.out.substr(at + 33, r.out.find('\n', at) - at - 33);
    EXPECT_NE(r.out.find("summary tick " + tick + " "), std::string::npos) << r.out;  // the run ended there
    EXPECT_EQ(r.out.find("the run ends here"), std::string::npos) << r.out;           // a replay ends quietly
    EXPECT_NE(r.out.find("(1 more left out at skill 1)"), std::string::npos) << r.out;  // the deathmatch-only wall
}

TEST(Changelevel, TouchingOneLoadsTheNextMapFromBesideTheLevel) {
    // The start pose stands in playtest.map's trigger_changelevel (Quake x 10.75, y 12.5).
    const auto r = game("--headless --ticks 30 --level " + kLevels + "/playtest.map --start-pose '10.75 1.656 -12.5 0 0'");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("changelevel playtest_end at tick 1\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("obscura: loaded " + fs::canonical(kLevels + "/playtest_end.map").string() + ": "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("obscura: level title: Playtest: the next level"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("summary tick 30 "), std::string::npos) << r.out;  // the next level plays its own ticks
}

TEST(Changelevel, AMissingOrEscapingNextMapEndsTheRunWithALine) {
    const std::string missing = roomWithExit("exit_missing.map", "nowhere");
    auto r = game("--headless --ticks 30 --level " + missing);
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find(missing + ":16: trigger_changelevel: no 'nowhere.map' beside " + missing + "; the run ends here"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("summary tick 1 "), std::string::npos) << r.out;

    r = game("--headless --ticks 30 --level " + roomWithExit("exit_escape.map", "../../etc/passwd"));
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("trigger_changelevel: 'map' '../../etc/passwd' is not a bare map name"), std::string::npos) << r.out;
}
