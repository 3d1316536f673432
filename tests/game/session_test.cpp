// The session builds the simulation without OGRE: misc_model colliders come from the plain
// .mesh reader (engine_ext/mesh), and the same settings give the same simulation.
#include <gtest/gtest.h>

#include "session.h"

#include "../map/test_maps.h"

#include <filesystem>
#include <fstream>

using namespace obscura;
using obscura::map::testdata::cube;
namespace fs = std::filesystem;

namespace {
Settings settingsFor(const std::string& level) {
    Settings s;
    s.level = level;
    s.dataDir = OBSCURA_SOURCE_DIR;
    return s;
}

Session load(const Settings& s) { return Session(s, Session::loadLevel(s, nullptr), {0, 1, 0}); }
}  // namespace

TEST(Session, AMiscModelBecomesAColliderWithoutTheRenderer) {
    const std::string map = std::string(OBSCURA_SOURCE_DIR) + "/tests/ssao/views/sibenik.map";
    // The .map names media/third_party/scenes/sibenik.mesh, found from the data folder. It has no brushes:
    // the player stands on the cathedral's floor only if the model became a collider.
    const Settings s = settingsFor(map);
    std::vector<std::string> warnings;
    Session a(s, Session::loadLevel(s, &warnings), {0, 1, 0});
    ASSERT_EQ(a.level().models.size(), 1u);
    ASSERT_TRUE(a.level().brushes.empty());
    for (int t = 0; t < 60; ++t) a.step({});
    EXPECT_TRUE(a.sim().player().onGround);
    EXPECT_GT(a.sim().player().feet.y, -1.0);
}

TEST(Session, AMissingModelIsALoadError) {
    const std::string map = (fs::path(testing::TempDir()) / "session_model.map").string();
    std::ofstream(map) << "{\n\"classname\" \"worldspawn\"\n"
                          "{\n( -64 -64 -16 ) ( -64 -63 -16 ) ( -64 -64 -15 ) tex 0 0 0 1 1\n"
                          "( 64 64 16 ) ( 64 64 17 ) ( 64 65 16 ) tex 0 0 0 1 1\n"
                          "( -64 -64 -16 ) ( -64 -64 -15 ) ( -63 -64 -16 ) tex 0 0 0 1 1\n"
                          "( 64 64 16 ) ( 65 64 16 ) ( 64 64 17 ) tex 0 0 0 1 1\n"
                          "( -64 -64 -16 ) ( -63 -64 -16 ) ( -64 -63 -16 ) tex 0 0 0 1 1\n"
                          "( 64 64 16 ) ( 64 65 16 ) ( 65 64 16 ) tex 0 0 0 1 1\n}\n}\n"
                          "{\n\"classname\" \"misc_model\"\n\"origin\" \"0 0 32\"\n\"model\" \"nothere.mesh\"\n}\n";
    try {
        load(settingsFor(map));
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("misc_model 'model' 'nothere.mesh' not found"), std::string::npos) << e.what();
    }
}

TEST(Session, TheSameSettingsGiveTheSameSimulation) {
    const Settings s = settingsFor(std::string(OBSCURA_SOURCE_DIR) + "/media/levels/arena.map");
    Session a(s, Session::loadLevel(s, nullptr), {0, 1, 0});
    Session b(s, Session::loadLevel(s, nullptr), {0, 1, 0});
    sim::PlayerCommand walk;
    walk.forward = 1;
    for (int t = 0; t < 30; ++t) {
        a.step(walk);
        b.step(walk);
    }
    EXPECT_EQ(a.sim().stateHash(), b.sim().stateHash());
    EXPECT_EQ(a.tick(), 30u);
}

TEST(Session, AMessageIsCentrePrintedForTwoSeconds) {
    // A floor and a trigger_once round the player start whose message has Quake's "\n".
    const std::string map = (fs::path(testing::TempDir()) / "session_message.map").string();
    std::ofstream(map) << "{\n\"classname\" \"worldspawn\"\n\"message\" \"A title, not centre-printed\"\n"
                       << cube(-256, -256, -512, "floor", 512) << "}\n"
                       << "{\n\"classname\" \"info_player_start\"\n\"origin\" \"0 0 24\"\n}\n"
                       << "{\n\"classname\" \"trigger_once\"\n\"message\" \"line one\\nline two\"\n" << cube(-64, -64, 0, "trigger", 128)
                       << "}\n";
    const Settings s = settingsFor(map);
    Session session(s, Session::loadLevel(s, nullptr), {0, 1, 0});
    EXPECT_EQ(session.centreMessage(), "");  // the title goes to the load line, not the HUD
    session.step({});
    EXPECT_EQ(session.centreMessage(), "line one\nline two");
    for (int t = 1; t < 120; ++t) session.step({});
    EXPECT_EQ(session.centreMessage(), "line one\nline two");  // 2 s at 60 Hz
    session.step({});
    EXPECT_EQ(session.centreMessage(), "");
}
