// Skill and deathmatch spawnflags (map/spawnflags.h): what Quake leaves out at each skill in single
// player is left out of the Level, brushes and all, and the load summary counts it.
#include <gtest/gtest.h>

#include "map/load_report.h"
#include "map/map_compile.h"
#include "test_maps.h"

using namespace obscura::map;
using testdata::cube;
using testdata::entity;

namespace {
// A worldspawn (flagged too: never left out), then one light per flag set and a deathmatch-only
// func_wall with a brush (E1M1's exit walls: 1792).
std::string flaggedLevel() {
    std::string text = entity("\"classname\" \"worldspawn\"\n\"spawnflags\" \"1792\"", cube(0, 0, 0));
    for (const char* flags : {"0", "256", "512", "1024", "768", "1536", "2048", "1 ", " 513", "junk"})
        text += entity("\"classname\" \"light\"\n\"origin\" \"32 32 32\"\n\"spawnflags\" \"" + std::string(flags) + "\"");
    text += entity("\"classname\" \"func_wall\"\n\"spawnflags\" \"1792\"", cube(128, 0, 0));
    return text;
}

Level atSkill(int skill) {
    CompileOptions o;
    o.skill = skill;
    return compileLevel(parseMap(flaggedLevel(), "t.map"), o);
}
}  // namespace

TEST(Spawnflags, EachSkillLeavesOutWhatQuakeLeavesOut) {
    EXPECT_TRUE(leftOutAtSkill(kSpawnNotEasy, 0));
    EXPECT_FALSE(leftOutAtSkill(kSpawnNotEasy, 1));
    EXPECT_TRUE(leftOutAtSkill(kSpawnNotMedium, 1));
    EXPECT_TRUE(leftOutAtSkill(kSpawnNotHard, 2));
    EXPECT_TRUE(leftOutAtSkill(kSpawnNotHard, 3));  // nightmare spawns as hard
    EXPECT_FALSE(leftOutAtSkill(kSpawnNotDeathmatch, 1));  // single player keeps them
    for (int skill = kMinSkill; skill <= kMaxSkill; ++skill) EXPECT_TRUE(leftOutAtSkill(1792, skill)) << skill;

    // Left out of 11 entities after worldspawn: 256, 768, 1792 at easy; 512, 768, 1536, 513, 1792 at
    // normal; 1024, 1536, 1792 at hard and nightmare.
    const int expected[] = {3, 5, 3, 3};
    for (int skill = kMinSkill; skill <= kMaxSkill; ++skill) {
        const Level l = atSkill(skill);
        EXPECT_EQ(l.leftOutEntities, expected[skill]) << skill;
        EXPECT_EQ(l.entities.size(), 12u - static_cast<std::size_t>(expected[skill])) << skill;
        EXPECT_EQ(l.skill, skill);
        ASSERT_EQ(l.brushes.size(), 1u) << skill;  // the func_wall's brush is gone, worldspawn's stays
        EXPECT_EQ(l.brushes[0].entityIndex, 0);
        for (const LevelEntity& e : l.entities)
            if (e.classname != "worldspawn") EXPECT_NE(e.value("spawnflags"), "1792") << e.classname;
    }
}

TEST(Spawnflags, IndicesStayDenseAndTheSummaryCountsWhatWasLeftOut) {
    const std::string text = entity("\"classname\" \"worldspawn\"", cube(0, 0, 0)) +
                             entity("\"classname\" \"func_wall\"\n\"spawnflags\" \"512\"", cube(128, 0, 0)) +
                             entity("\"classname\" \"func_wall\"", cube(256, 0, 0));
    const Level l = compileLevel(parseMap(text, "t.map"));
    ASSERT_EQ(l.entities.size(), 2u);
    ASSERT_EQ(l.brushes.size(), 2u);
    EXPECT_EQ(l.brushes[1].entityIndex, 1);  // the kept func_wall, not the map's third entity
    EXPECT_EQ(l.entities[static_cast<std::size_t>(l.brushes[1].entityIndex)].classname, "func_wall");
    EXPECT_NE(summaryLine(l, 0, {}).find("2 entities (1 more left out at skill 1), "), std::string::npos) << summaryLine(l, 0, {});
    EXPECT_EQ(summaryLine(compileLevel(parseMap(entity("\"classname\" \"worldspawn\""), "t.map")), 0, {}).find("left out"),
              std::string::npos);
}

TEST(Spawnflags, ASkillOutOfRangeIsAnError) {
    CompileOptions o;
    o.skill = 4;
    EXPECT_THROW(compileLevel(parseMap(entity("\"classname\" \"worldspawn\""), "t.map"), o), MapError);
}
