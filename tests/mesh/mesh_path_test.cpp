// findModelFile: the misc_model lookup.
#include "mesh/model_path.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

using obscura::mesh::findModelFile;
namespace fs = std::filesystem;

TEST(MeshModelPath, SearchOrderAbsoluteAndMissing) {
    const fs::path root = fs::temp_directory_path() / ("obscura-model-path-" + std::to_string(::getpid()));
    fs::create_directories(root / "a");
    fs::create_directories(root / "b" / "sub");
    fs::create_directories(root / "a" / "dir.mesh");  // a folder, not a model
    for (const fs::path& p : {root / "a" / "x.mesh", root / "b" / "x.mesh", root / "b" / "y.mesh", root / "b" / "sub" / "z.mesh"})
        std::ofstream(p.string()) << "m";
    const std::vector<std::string> dirs = {(root / "a").string(), (root / "b").string()};
    const std::string canon = fs::canonical(root).string();
    EXPECT_EQ(findModelFile("x.mesh", dirs), canon + "/a/x.mesh");  // the first folder wins
    EXPECT_EQ(findModelFile("y.mesh", dirs), canon + "/b/y.mesh");
    EXPECT_EQ(findModelFile("sub/../sub/z.mesh", dirs), canon + "/b/sub/z.mesh");
    EXPECT_EQ(findModelFile((root / "b" / "y.mesh").string(), {}), canon + "/b/y.mesh");
    EXPECT_EQ(findModelFile("dir.mesh", dirs), "");
    EXPECT_EQ(findModelFile("none.mesh", dirs), "");
    EXPECT_EQ(findModelFile("", dirs), "");
    fs::remove_all(root);
}
