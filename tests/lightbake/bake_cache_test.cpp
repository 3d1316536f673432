// The light bake's cache (lightbake/bake_cache.h): a hit gives the bake back exactly, and a
// changed level, a truncated, corrupt or foreign file is baked again with the reason.
#include "bake_levels.h"
#include "lightbake/bake_cache.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace obscura;
using namespace obscura::lightbake;
using namespace obscura::lightbake::testdata;

namespace {
namespace fs = std::filesystem;

std::string level(int lampX) {
    return "{\n\"classname\" \"worldspawn\"\n" + room(0, 0, 256, 256, 128, 16) + "}\n{\n\"classname\" \"light\"\n\"origin\" \"" +
           std::to_string(lampX) + " 128 64\"\n}\n";
}

struct TempDir {
    fs::path path = fs::temp_directory_path() / ("obscura_lightbake_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                                 "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    TempDir() { fs::remove_all(path); }
    ~TempDir() { fs::remove_all(path); }
};

BakeOutcome bake(const map::Level& l, const std::string& dir, std::vector<std::string>& lines) {
    BakeSettings s;
    s.probeCell = 2;
    return bakeOrLoad(l, bakeSkyOf(l), s, dir, [&](const std::string& line) { lines.push_back(line); });
}
}  // namespace

TEST(LightBakeCache, AHitGivesTheBakeBackAndAChangedLevelBakesAgain) {
    TempDir dir;
    map::Level a = compile(level(64));
    a.sourcePath = "/levels/t.map";
    std::vector<std::string> lines;
    const BakeOutcome first = bake(a, dir.path.string(), lines);
    EXPECT_FALSE(first.fromCache);
    EXPECT_TRUE(lines.empty()) << "a missing file is baked quietly: " << lines.front();
    ASSERT_TRUE(fs::exists(first.file));
    EXPECT_EQ(fs::path(first.file).parent_path(), dir.path / "lightbake");

    const BakeOutcome second = bake(a, dir.path.string(), lines);
    EXPECT_TRUE(second.fromCache);
    ASSERT_EQ(second.bake.direct.size(), first.bake.direct.size());
    // Stored as half floats, and a fresh bake is rounded the same way: the run that baked and the
    // runs that read it back see the same light, bit for bit.
    EXPECT_EQ(second.bake.direct, first.bake.direct);
    EXPECT_EQ(second.bake.indirect, first.bake.indirect);
    EXPECT_EQ(second.bake.probes.up, first.bake.probes.up);
    EXPECT_EQ(second.bake.probes.down, first.bake.probes.down);
    EXPECT_EQ(second.bake.probes.count(), first.bake.probes.count());

    map::Level moved = compile(level(192));  // the lamp moved: same file name, new content
    moved.sourcePath = a.sourcePath;
    lines.clear();
    const BakeOutcome third = bake(moved, dir.path.string(), lines);
    EXPECT_FALSE(third.fromCache);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_NE(lines[0].find("stale"), std::string::npos) << lines[0];
    EXPECT_NE(third.bake.direct, first.bake.direct);
    EXPECT_TRUE(bake(moved, dir.path.string(), lines).fromCache) << "the new bake replaced the old";
}

TEST(LightBakeCache, ATruncatedCorruptOrForeignFileIsBakedAgainWithOneLine) {
    TempDir dir;
    map::Level a = compile(level(64));
    a.sourcePath = "/levels/t.map";
    std::vector<std::string> lines;
    const BakeOutcome first = bake(a, dir.path.string(), lines);
    const auto size = fs::file_size(first.file);
    const std::vector<std::pair<std::string, std::function<void()>>> damages = {
        {"truncated", [&] { fs::resize_file(first.file, size / 2); }},
        {"checksum", [&] {
             std::fstream f(first.file, std::ios::in | std::ios::out | std::ios::binary);
             f.seekp(static_cast<std::streamoff>(size / 2));
             f.put('\x55');
         }},
        {"not a light bake", [&] { std::ofstream(first.file, std::ios::trunc) << "hello"; }},
    };
    for (const auto& [expected, damage] : damages) {
        bake(a, dir.path.string(), lines);  // whole again
        damage();
        lines.clear();
        const BakeOutcome again = bake(a, dir.path.string(), lines);
        EXPECT_FALSE(again.fromCache) << expected;
        ASSERT_EQ(lines.size(), 1u) << expected;
        EXPECT_NE(lines[0].find(expected), std::string::npos) << lines[0];
        EXPECT_NE(lines[0].find(first.file), std::string::npos) << "the line names the file: " << lines[0];
        EXPECT_EQ(again.bake.direct, first.bake.direct) << expected;
        EXPECT_TRUE(bake(a, dir.path.string(), lines).fromCache) << "rebuilt: " << expected;
    }
}

TEST(LightBakeCache, TheFileIsNamedByTheLevelInsideTheCacheFolderOnly) {
    const std::string f = cacheFile("/c", "../../etc/passwd");
    EXPECT_EQ(f.rfind("/c/lightbake/passwd-", 0), 0u) << f;
    EXPECT_NE(cacheFile("/c", "/a/t.map"), cacheFile("/c", "/b/t.map")) << "two levels of one name";
}
