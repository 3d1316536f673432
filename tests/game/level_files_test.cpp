// Every entry point that opens a file a level names goes through map::LevelFiles / resolveAsset
// (engine_ext/map/asset_path.h): the colliders (Session), the reference tools (addModelTriangles),
// decal_sign images, light_sign fonts and the `.ent` overlay. Each is fed an escaping path, a
// symlink out of the roots, a device file and a FIFO inside the level's folder. A FIFO that anything
// opened would block the test until ctest's timeout, so "refused" here means "never opened".
// (The renderer's placeModel uses the same LevelFiles::find; a game run never reaches it with such
// a name, because the colliders refuse it first: tests/game/headless_test.cpp.)
#include <gtest/gtest.h>

#include "decals/decal_sign.h"
#include "map/asset_path.h"
#include "map/map_compile.h"
#include "raytrace/level_triangles.h"
#include "session.h"
#include "signs/sign_light.h"

#include <filesystem>
#include <fstream>
#include <functional>

#include <sys/stat.h>

using namespace obscura;
namespace fs = std::filesystem;

namespace {
const char* kRoom =
    "{\n\"classname\" \"worldspawn\"\n"
    "{\n( -64 -64 -16 ) ( -64 -63 -16 ) ( -64 -64 -15 ) tex 0 0 0 1 1\n"
    "( 64 64 16 ) ( 64 64 17 ) ( 64 65 16 ) tex 0 0 0 1 1\n"
    "( -64 -64 -16 ) ( -64 -64 -15 ) ( -63 -64 -16 ) tex 0 0 0 1 1\n"
    "( 64 64 16 ) ( 65 64 16 ) ( 64 64 17 ) tex 0 0 0 1 1\n"
    "( -64 -64 -16 ) ( -63 -64 -16 ) ( -64 -63 -16 ) tex 0 0 0 1 1\n"
    "( 64 64 16 ) ( 64 65 16 ) ( 65 64 16 ) tex 0 0 0 1 1\n}\n}\n";

// A level folder beside a private one: lvl/link.* leads into private/, lvl/fifo.* is a FIFO.
struct Tree {
    fs::path base = fs::path(testing::TempDir()) /
                    ("level_files_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::path level = base / "lvl", outside = base / "private";
    Tree() {
        fs::remove_all(base);
        fs::create_directories(level);
        fs::create_directories(outside);
        for (const char* ext : {"mesh", "png", "ttf", "ent"}) {
            const fs::path secret = outside / (std::string("secret.") + ext);
            std::ofstream(secret.string()) << "secret";
            fs::create_symlink(secret, level / (std::string("link.") + ext));
            EXPECT_EQ(::mkfifo((level / (std::string("fifo.") + ext)).c_str(), 0600), 0);
        }
    }
    ~Tree() {
        std::error_code ignored;
        fs::remove_all(base, ignored);
    }
    Tree(const Tree&) = delete;
    Tree& operator=(const Tree&) = delete;
    std::string write(const std::string& name, const std::string& entities) const {
        const std::string path = (level / name).string();
        std::ofstream(path) << kRoom << entities;
        return path;
    }
};

struct Case {
    std::string name;  // what the level names
    std::string why;   // a part of the error
};

// An escaping path, a symlink out, a device and a FIFO inside the level's folder.
std::vector<Case> badNames(const Tree& t, const std::string& ext) {
    const std::string secret = fs::canonical(t.outside / ("secret." + ext)).string();
    return {{"../private/secret." + ext, "resolves to '" + secret + "', outside"},
            {"../../../../../../../../../../etc/passwd", "resolves to '/etc/passwd', outside"},
            {"link." + ext, "resolves to '" + secret + "', outside"},
            {"/dev/zero", "resolves to '/dev/zero', outside"},
            {"fifo." + ext, "no regular file (a device or a FIFO)"}};
}

std::string modelEntity(const std::string& model) {
    return "{\n\"classname\" \"misc_model\"\n\"origin\" \"0 0 0\"\n\"model\" \"" + model + "\"\n}\n";
}

std::string thrown(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no error)";
}

Settings settingsFor(const std::string& level) {
    Settings s;
    s.level = level;
    s.dataDir = OBSCURA_SOURCE_DIR;
    return s;
}
}  // namespace

TEST(LevelFiles, TheCollidersRefuseEveryNameOutsideTheRoots) {
    const Tree t;
    for (const Case& c : badNames(t, "mesh")) {
        const Settings s = settingsFor(t.write("m.map", modelEntity(c.name)));
        const std::string error = thrown([&] { Session(s, Session::loadLevel(s, nullptr), {0, 1, 0}); });
        EXPECT_NE(error.find("m.map:12: misc_model 'model'"), std::string::npos) << c.name << ": " << error;
        EXPECT_NE(error.find(c.why), std::string::npos) << c.name << ": " << error;
    }
}

TEST(LevelFiles, TheReferenceToolsRefuseEveryNameOutsideTheRoots) {
    const Tree t;
    for (const Case& c : badNames(t, "mesh")) {
        const std::string path = t.write("m.map", modelEntity(c.name));
        const map::Level level = map::loadLevel(path);
        std::vector<TriangleMesh> out;
        const std::string error = thrown([&] { addModelTriangles(level, map::levelSearchDirs(path, OBSCURA_SOURCE_DIR), out); });
        EXPECT_NE(error.find(c.why), std::string::npos) << c.name << ": " << error;
        EXPECT_TRUE(out.empty());
    }
}

TEST(LevelFiles, DecalSignImagesOutsideTheRootsAreSkipped) {
    const Tree t;
    for (const Case& c : badNames(t, "png")) {
        const std::string path = t.write(
            "d.map", "{\n\"classname\" \"decal_sign\"\n\"origin\" \"0 63 0\"\n\"angle\" \"270\"\n\"image\" \"" + c.name + "\"\n}\n");
        std::vector<std::string> warnings;
        EXPECT_TRUE(decals::readSigns(map::loadLevel(path), map::levelSearchDirs(path, OBSCURA_SOURCE_DIR), warnings).empty());
        ASSERT_EQ(warnings.size(), 1u) << c.name;
        EXPECT_NE(warnings[0].find(c.why), std::string::npos) << c.name << ": " << warnings[0];
    }
}

TEST(LevelFiles, LightSignFontsOutsideTheFontFoldersAreSkipped) {
    const Tree t;
    // A font is a bare name (a path is refused as such); a link or a FIFO in a font folder is not read.
    for (const Case& c : std::vector<Case>{{"link.ttf", "outside the font folders"},
                                           {"fifo.ttf", "no regular file"},
                                           {"../private/secret.ttf", "is not a bare file name"}}) {
        const std::string path = t.write(
            "f.map", "{\n\"classname\" \"light_sign\"\n\"origin\" \"0 63 0\"\n\"angle\" \"270\"\n\"text\" \"EXIT\"\n\"font\" \"" +
                         c.name + "\"\n}\n");
        std::vector<std::string> warnings;
        EXPECT_TRUE(signs::readSignLights(map::loadLevel(path), {t.level.string()}, warnings).empty());
        ASSERT_FALSE(warnings.empty()) << c.name;
        EXPECT_NE(warnings.back().find(c.why), std::string::npos) << c.name << ": " << warnings.back();
    }
}

TEST(LevelFiles, AnOverlayThatLinksOutOrIsAFifoIsALoadError) {
    const Tree t;
    for (const Case& c : std::vector<Case>{{"link", "outside the level's folder"}, {"fifo", "no regular file"}}) {
        const Settings s = settingsFor(t.write(c.name + ".map", ""));
        const std::string error = thrown([&] { Session::loadLevel(s, nullptr); });
        EXPECT_NE(error.find("entity overlay '" + c.name + ".ent' resolves to"), std::string::npos) << error;
        EXPECT_NE(error.find(c.why), std::string::npos) << error;
    }
    const Settings plain = settingsFor(t.write("plain.map", ""));  // no overlay: loads
    EXPECT_EQ(thrown([&] { Session::loadLevel(plain, nullptr); }), "(no error)");
}
