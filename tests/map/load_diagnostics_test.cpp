// The game's stderr when it loads a level: each map warning as `file:line: text`, and one summary
// line with the load's times, counts and unknown classes by name (tests/map/levels/diagnostics.map).
#include <gtest/gtest.h>

#include "run_process.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

// The game's stderr alone (stdout discarded), for a headless run of one tick.
obscura::testing_support::ProcessResult stderrOf(const std::string& level) {
    return obscura::testing_support::runProcess("{ '" OBSCURA_GAME "' --headless --ticks 1 --width 64 --height 64 --level '" + level +
                                                "' 2>&1 1>/dev/null; }");
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream is(text);
    for (std::string l; std::getline(is, l);) out.push_back(l);
    return out;
}

TEST(LoadDiagnostics, WarningsWithFileAndLineAndOneSummary) {
    const std::string map = OBSCURA_SOURCE_DIR "/tests/map/levels/diagnostics.map";
    const auto r = stderrOf(map);
    ASSERT_EQ(r.code, 0) << r.out;
    const auto all = lines(r.out);
    const auto count = [&](const std::string& what) {
        int n = 0;
        for (const auto& l : all) n += l.find(what) != std::string::npos;
        return n;
    };
    EXPECT_EQ(count(map + ":20: brush skipped: "), 1) << r.out;
    EXPECT_EQ(count(map + ":33: 'light' value 'bright' is not a number"), 1) << r.out;
    ASSERT_EQ(count("obscura: loaded "), 1) << r.out;
    const std::regex summary("obscura: loaded " + std::regex_replace(map, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
                             R"(: parse \d+\.\d ms, compile \d+\.\d ms, session \d+\.\d ms, scene \d+\.\d ms; )"
                             R"(1 brushes, 6 entities, 1 lights, 0 models; 2 warnings; )"
                             "unknown classes: monster_army \u00d72, item_health \u00d71");
    bool found = false;
    for (const auto& l : all) found |= std::regex_match(l, summary);
    EXPECT_TRUE(found) << r.out;
}

TEST(LoadDiagnostics, ManyWarningsAreCutWithACount) {
    // 30 brushes of three planes each: 20 lines, then the count of the other 10.
    const std::string map = (std::filesystem::path(testing::TempDir()) / "many_warnings.map").string();
    std::ofstream out(map);
    out << "{\n\"classname\" \"worldspawn\"\n";
    out << "{\n( 0 0 -16 ) ( 0 1 -16 ) ( 0 0 -15 ) f 0 0 0 1 1\n( 0 0 -16 ) ( 0 0 -15 ) ( 1 0 -16 ) f 0 0 0 1 1\n"
           "( 0 0 -16 ) ( 1 0 -16 ) ( 0 1 -16 ) f 0 0 0 1 1\n( 64 64 0 ) ( 64 65 0 ) ( 65 64 0 ) f 0 0 0 1 1\n"
           "( 64 64 0 ) ( 65 64 0 ) ( 64 64 1 ) f 0 0 0 1 1\n( 64 64 0 ) ( 64 64 1 ) ( 64 65 0 ) f 0 0 0 1 1\n}\n";
    for (int i = 0; i < 30; ++i) out << "{\n( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) f 0 0 0 1 1\n( 0 0 0 ) ( 0 0 1 ) ( 0 1 0 ) f 0 0 0 1 1\n}\n";
    out << "}\n{\n\"classname\" \"info_player_start\"\n\"origin\" \"32 32 24\"\n}\n";
    out.close();
    const auto r = stderrOf(map);
    ASSERT_EQ(r.code, 0) << r.out;
    int shown = 0;
    for (const auto& l : lines(r.out)) shown += l.rfind(map + ":", 0) == 0 && l.find("brush skipped") != std::string::npos;
    EXPECT_EQ(shown, 20) << r.out;
    EXPECT_NE(r.out.find("obscura: ... and 10 more warnings (see the log)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("; 30 warnings; unknown classes: none"), std::string::npos) << r.out;
}

}  // namespace
