// Entity overlays (map::addEntityOverlay): Obscura's own point entities added to a level it may not
// edit, each keeping its own file for messages; a malformed overlay names its file and line.
#include <gtest/gtest.h>

#include "map/map_compile.h"
#include "signs/sign_light.h"

#include <filesystem>
#include <fstream>

using namespace obscura;
namespace fs = std::filesystem;

namespace {
std::string write(const std::string& name, const std::string& text) {
    const fs::path p = fs::path(testing::TempDir()) / ("overlay_" + name);
    std::ofstream(p.string()) << text;
    return p.string();
}
const std::string kLevel = (fs::path(OBSCURA_SOURCE_DIR) / "tests/signs/levels/sign_room.map").string();
}  // namespace

TEST(EntityOverlay, PointEntitiesJoinTheLevelAndKeepTheirFile) {
    map::MapFile file = map::loadMapFile(kLevel);
    const std::size_t before = file.entities.size();
    const std::string overlay = write("good.ent",
                                      "// a comment\n{\n\"classname\" \"light_sign\"\n\"origin\" \"256 128 64\"\n\"text\" \"\"\n}\n"
                                      "{\n\"classname\" \"info_null\"\n\"origin\" \"0 0 0\"\n}\n");
    map::addEntityOverlay(file, overlay);
    ASSERT_EQ(file.entities.size(), before + 2);
    const map::Level level = map::compileLevel(file);
    const map::LevelEntity& added = level.entities[before];
    EXPECT_EQ(added.classname, "light_sign");
    EXPECT_EQ(added.where(level.sourcePath), overlay + ":2");
    EXPECT_EQ(level.entities.front().where(level.sourcePath), level.sourcePath + ":" + std::to_string(level.entities.front().pos.line));
    // A sign's message names the overlay's line, not the level's (its text is empty: skipped).
    std::vector<std::string> warnings;
    const auto signs = signs::readSignLights(level, {"/usr/share/fonts/truetype/dejavu"}, warnings);
    EXPECT_EQ(signs.size(), 1u);  // the level's own sign; the overlay's is skipped
    bool named = false;
    for (const auto& w : warnings) named |= w.rfind(overlay + ":2: light_sign skipped", 0) == 0;
    EXPECT_TRUE(named) << (warnings.empty() ? std::string("no warnings") : warnings.front());
}

TEST(EntityOverlay, BrushesWorldspawnAndBadSyntaxAreRefusedWithFileAndLine) {
    map::MapFile file = map::loadMapFile(kLevel);
    const std::string brushes = write("brush.ent", "{\n\"classname\" \"func_door\"\n{\n( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) a 0 0 0 1 1\n"
                                                   "( 0 0 8 ) ( 1 0 8 ) ( 0 1 8 ) a 0 0 0 1 1\n}\n}\n");
    try {
        map::addEntityOverlay(file, brushes);
        FAIL() << "an overlay with brushes was taken";
    } catch (const map::MapError& e) {
        EXPECT_EQ(std::string(e.what()), brushes + ":1: an entity overlay holds point entities only, this one has brushes");
    }
    const std::string world = write("world.ent", "\n{\n\"classname\" \"worldspawn\"\n}\n");
    EXPECT_THROW(map::addEntityOverlay(file, world), map::MapError);
    const std::string bad = write("bad.ent", "{\n\"classname\" \"light_sign\"\n\"origin\" \n");
    try {
        map::addEntityOverlay(file, bad);
        FAIL() << "a malformed overlay was taken";
    } catch (const map::MapError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(bad + ":", 0), 0u) << e.what();
    }
}
