// Every entity class and key the game's code reads by name is in the registry (entity_classes.cpp):
// the sources that handle entities (every engine_ext/ and game/ file naming LevelEntity or
// MapEntity) are scanned for `classname == "x"` and for key reads (`.value("k"`, `.has("k"`,
// `numberKey(level, e, "k"`, ...). A key only has to be listed for some class (the scan cannot
// tell which entity a read is for); the scanner is shown to catch a class and a key not listed.
#include <gtest/gtest.h>

#include "map/entity_classes.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace obscura::map {
namespace {

namespace fs = std::filesystem;

std::set<std::string> registryKeys() {
    std::set<std::string> keys(std::begin(kImplicitKeys), std::end(kImplicitKeys));
    for (const EntityClass& c : entityClasses())
        for (const EntityKey& k : allKeys(c)) keys.insert(k.name);
    return keys;
}

// What `text` (from `file`) reads by name that the registry lacks, one line each.
std::vector<std::string> unlisted(const std::string& text, const std::string& file) {
    // e.value("k"  e.has("k"  number(me, "k"  vec(me, "k"  numberKey(level, e, "k"  metres("k"
    static const std::regex keyRead(
        R"((?:\.value\(|\.has\(|\b(?:number|vec)\(me, |\bnumberKey\(level, e, |\bmetres\()\"([A-Za-z_0-9]+)\")");
    static const std::regex classTest(R"(\b(?:classname|c) [!=]= \"([A-Za-z_0-9]+)\")");
    static const std::set<std::string> keys = registryKeys();
    std::vector<std::string> out;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), keyRead); it != std::sregex_iterator(); ++it)
        if (!keys.count((*it)[1])) out.push_back(file + ": key '" + (*it)[1].str() + "' is read but not in the registry");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), classTest); it != std::sregex_iterator(); ++it)
        if (!isKnownClass((*it)[1].str())) out.push_back(file + ": class '" + (*it)[1].str() + "' is read but not in the registry");
    return out;
}

std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}

TEST(EntityReads, EveryClassAndKeyTheSourcesReadIsInTheRegistry) {
    std::vector<std::string> problems;
    std::vector<std::string> scanned;
    for (const char* dir : {"engine_ext", "game"})
        for (const auto& entry : fs::recursive_directory_iterator(fs::path(OBSCURA_SOURCE_DIR) / dir)) {
            const auto ext = entry.path().extension();
            if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
            const std::string text = readAll(entry.path());
            if (text.find("LevelEntity") == std::string::npos && text.find("MapEntity") == std::string::npos) continue;
            scanned.push_back(entry.path().filename().string());
            for (auto& p : unlisted(text, entry.path().string())) problems.push_back(p);
        }
    std::string all;
    for (const auto& p : problems) all += p + "\n";
    EXPECT_TRUE(problems.empty()) << all;
    // The files that read entities today are among those scanned (the scan is not empty by mistake).
    for (const char* f : {"map_compile.cpp", "physics_world.cpp", "combat.cpp", "decal_sign.cpp", "map_lights.cpp", "movers.cpp", "triggers.cpp"})
        EXPECT_NE(std::find(scanned.begin(), scanned.end(), f), scanned.end()) << f;
}

TEST(EntityReads, TheScanCatchesAnUnlistedClassAndKey) {
    const auto p = unlisted("if (e.classname == \"prop_keg\") v = numberKey(level, e, \"volume\", 1, 0, 2, \"l\");\n"
                            "if (e.classname == \"prop_crate\") w = e.value(\"mass\");",
                            "x.cpp");
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0], "x.cpp: key 'volume' is read but not in the registry");
    EXPECT_EQ(p[1], "x.cpp: class 'prop_keg' is read but not in the registry");
}

}  // namespace
}  // namespace obscura::map
