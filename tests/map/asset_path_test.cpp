// Level asset paths stay inside the level's folder and the media roots (symlinks and `..` resolved).
#include <gtest/gtest.h>

#include "map/asset_path.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

using namespace obscura::map;
namespace fs = std::filesystem;

namespace {
// One tree per test: ctest runs this file's tests as separate processes in parallel, and a shared
// folder let one test's remove_all meet another's files (CI: "cannot remove: Directory not empty").
fs::path treeFolder() {
    return fs::path(testing::TempDir()) /
           ("asset_tree_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
}

struct Tree {
    fs::path base = treeFolder();
    fs::path level = base / "levels", media = base / "media", outside = base / "private";
    Tree() {
        fs::remove_all(base);
        for (const auto& d : {level / "models", media, outside}) fs::create_directories(d);
        std::ofstream((level / "models" / "crate.mesh").string()) << "m";
        std::ofstream((media / "tree.mesh").string()) << "m";
        std::ofstream((outside / "secret.mesh").string()) << "s";
        fs::create_symlink(outside / "secret.mesh", level / "link.mesh");
        fs::create_symlink(media / "tree.mesh", level / "ok_link.mesh");
    }
    ~Tree() {
        std::error_code ignored;
        fs::remove_all(base, ignored);
    }
    Tree(const Tree&) = delete;
    Tree& operator=(const Tree&) = delete;
    std::vector<std::string> dirs() const { return {level.string()}; }
    std::vector<std::string> roots() const { return {level.string(), media.string()}; }
};
}  // namespace

TEST(AssetPath, FilesInsideTheRootsResolve) {
    const Tree t;
    EXPECT_EQ(resolveAsset("models/crate.mesh", t.dirs(), t.roots()).file, fs::canonical(t.level / "models/crate.mesh").string());
    EXPECT_EQ(resolveAsset("models/../models/crate.mesh", t.dirs(), t.roots()).file, fs::canonical(t.level / "models/crate.mesh").string());
    EXPECT_EQ(resolveAsset("../media/tree.mesh", t.dirs(), t.roots()).file, fs::canonical(t.media / "tree.mesh").string());
    EXPECT_EQ(resolveAsset((t.media / "tree.mesh").string(), t.dirs(), t.roots()).file, fs::canonical(t.media / "tree.mesh").string());
    EXPECT_EQ(resolveAsset("ok_link.mesh", t.dirs(), t.roots()).file, fs::canonical(t.media / "tree.mesh").string());
}

TEST(AssetPath, DotDotAbsolutePathsAndSymlinksOutsideAreRefused) {
    const Tree t;
    const std::string secret = fs::canonical(t.outside / "secret.mesh").string();
    for (const std::string& name : {std::string("../private/secret.mesh"), secret, std::string("link.mesh"),
                                    std::string("models/../../private/secret.mesh")}) {
        const AssetPath a = resolveAsset(name, t.dirs(), t.roots());
        EXPECT_TRUE(a.file.empty()) << name;
        EXPECT_EQ(a.error, "resolves to '" + secret + "', outside the level's folder and the media folders") << name;
    }
    const std::string deep = "../../../../../../../../../../etc/passwd";
    EXPECT_EQ(resolveAsset(deep, t.dirs(), t.roots()).error, "resolves to '/etc/passwd', outside the level's folder and the media folders");
    // A root that is itself a prefix string of another folder does not let that folder in.
    EXPECT_FALSE(resolveAsset(secret, t.dirs(), {(t.base / "priv").string()}).error.empty());
}

TEST(AssetPath, NamesThatAreNoFileGiveNeither) {
    const Tree t;
    const AssetPath a = resolveAsset("nothere.mesh", t.dirs(), t.roots());
    EXPECT_TRUE(a.file.empty());
    EXPECT_TRUE(a.error.empty());
    const AssetPath folder = resolveAsset("models", t.dirs(), t.roots());  // a folder is no mesh
    EXPECT_TRUE(folder.file.empty());
    EXPECT_EQ(folder.error, "resolves to '" + fs::canonical(t.level / "models").string() + "', which is a folder");
    EXPECT_TRUE(isBareName("cornell.mesh"));
    EXPECT_FALSE(isBareName("../cornell.mesh"));
    EXPECT_FALSE(isBareName("a\\b.mesh"));
    EXPECT_FALSE(isBareName(".."));
}

TEST(AssetPath, SearchFoldersAreTriedInOrder) {
    const Tree t;
    std::ofstream((t.media / "crate.mesh").string()) << "m";
    std::ofstream((t.media / "only_media.mesh").string()) << "m";
    const std::vector<std::string> dirs = {(t.level / "models").string(), t.media.string()};
    EXPECT_EQ(resolveAsset("crate.mesh", dirs, t.roots()).file, fs::canonical(t.level / "models/crate.mesh").string());  // the first wins
    EXPECT_EQ(resolveAsset("only_media.mesh", dirs, t.roots()).file, fs::canonical(t.media / "only_media.mesh").string());
    EXPECT_EQ(levelSearchDirs("/x/levels/a.map", "/data"), (std::vector<std::string>{"/x/levels", "/data", fs::current_path().string()}));
    const LevelFiles files((t.level / "a.map").string(), {t.level.string()});
    EXPECT_EQ(files.require("models/crate.mesh", "a.map:3: misc_model", "'model'"), fs::canonical(t.level / "models/crate.mesh").string());
    try {
        files.require("nothere.mesh", "a.map:3: misc_model", "'model'");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "a.map:3: misc_model 'model' 'nothere.mesh' not found (looked in the level's folder, the data folder and the working directory)");
    }
}
