// The load summary and the bounded warning lines the game prints on stderr.
#include <gtest/gtest.h>

#include "map/load_report.h"
#include "map/map_compile.h"
#include "test_maps.h"

namespace obscura::map {
namespace {

TEST(LoadReport, SummaryHasTimesCountsAndUnknownClassesMostFrequentFirst) {
    using testdata::cube;
    using testdata::entity;
    std::string text = entity("\"classname\" \"worldspawn\"", cube(0, 0, 0) + cube(100, 0, 0)) +
                       entity("\"classname\" \"light\"\n\"origin\" \"0 0 0\"");
    for (int i = 0; i < 4; ++i) text += entity("\"classname\" \"item_health\"\n\"origin\" \"0 0 0\"");
    for (int i = 0; i < 12; ++i) text += entity("\"classname\" \"monster_army\"\n\"origin\" \"0 0 0\"");
    text += entity("\"classname\" \"ambient_drip\"\n\"origin\" \"0 0 0\"") + entity("\"classname\" \"ambient_comp_hum\"\n\"origin\" \"0 0 0\"");
    const Level l = compileLevel(parseMap(text, "lvl.map"));
    LoadTimes t;
    t.parseMs = 1.24, t.compileMs = 2, t.sessionMs = 3, t.sceneMs = 40.04;
    EXPECT_EQ(summaryLine(l, 1, t),
              "obscura: loaded lvl.map: parse 1.2 ms, compile 2.0 ms, session 3.0 ms, scene 40.0 ms; 2 brushes, 20 entities, "
              "1 lights, 0 models; 1 warning; unknown classes: monster_army \u00d712, item_health \u00d74, ambient_comp_hum \u00d71, "
              "ambient_drip \u00d71");
}

TEST(LoadReport, AllKnownSaysNone) {
    const Level l = compileLevel(parseMap(testdata::entity("\"classname\" \"worldspawn\"", testdata::cube(0, 0, 0)), "a.map"));
    const std::string s = summaryLine(l, 0, {});
    EXPECT_NE(s.find("; 0 warnings; unknown classes: none"), std::string::npos) << s;
}

TEST(LoadReport, WarningsAreBounded) {
    std::vector<std::string> w;
    for (int i = 1; i <= 25; ++i) w.push_back("a.map:" + std::to_string(i) + ": brush skipped: fewer than 4 planes");
    const auto lines = warningLines(w);
    ASSERT_EQ(lines.size(), kMaxWarningLines + 1);
    EXPECT_EQ(lines.front(), w.front());
    EXPECT_EQ(lines[kMaxWarningLines - 1], w[kMaxWarningLines - 1]);
    EXPECT_EQ(lines.back(), "obscura: ... and 5 more warnings (see the log)");
    EXPECT_EQ(warningLines({w.begin(), w.begin() + 3}).size(), 3u);  // few: all, no tail
    EXPECT_TRUE(warningLines({}).empty());
}

}  // namespace
}  // namespace obscura::map
