// Every entity class and key the game's code reads by name is in the registry (entity_classes.cpp):
// the sources that handle entities (every engine_ext/ and game/ file naming LevelEntity or
// MapEntity) are scanned for `classname == "x"` and for key reads (`.value("k"`, `.has("k"`,
// `numberKey(level, e, "k"`, ...). A key only has to be listed for some class (the scan cannot
// tell which entity a read is for); the scanner is shown to catch a class and a key not listed.
#include <gtest/gtest.h>

#include "map/entity_classes.h"

#include <filesystem>
#include <algorithm>
#include <fstream>
#include <map>
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

// Every key name `text` reads, in every reader form the sources use:
//   e.value("k"  e->value("k"  e.has("k"  number(me, "k"  keys_.number(e, "k"  keys.positive(e, "k"  vec(me, "k"
//   numberOf(e, "k"  metresOf(e, "k"  readColour(e, "k"  numberKey(level, e, "k"  metres("k"
//   k.number({"k1", "k2"}  k.colour({..})  k.mangle({..})  k.find({..})  (map_lights.cpp's lists)
std::vector<std::string> keysRead(const std::string& text) {
    static const std::regex single(R"((?:(?:\.|->)value\(|(?:\.|->)has\(|\b(?:number|positive|vec|numberOf|metresOf|readColour)\((?:me|e), |)"
                                   R"(\bnumberKey\(level, e, |\bmetres\()\"([A-Za-z_0-9]+)\")");
    static const std::regex list(R"(\b(?:number|colour|mangle|find)\(\{([^}]*)\})");
    static const std::regex quoted(R"(\"([A-Za-z_0-9]+)\")");
    std::vector<std::string> out;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), single); it != std::sregex_iterator(); ++it) out.push_back((*it)[1]);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), list); it != std::sregex_iterator(); ++it) {
        const std::string names = (*it)[1];
        for (auto q = std::sregex_iterator(names.begin(), names.end(), quoted); q != std::sregex_iterator(); ++q) out.push_back((*q)[1]);
    }
    return out;
}

// What `text` (from `file`) reads by name that the registry lacks, one line each.
std::vector<std::string> unlisted(const std::string& text, const std::string& file) {
    static const std::regex classTest(R"(\b(?:classname|c) [!=]= \"([A-Za-z_0-9]+)\")");
    static const std::set<std::string> keys = registryKeys();
    std::vector<std::string> out;
    for (const std::string& k : keysRead(text))
        if (!keys.count(k)) out.push_back(file + ": key '" + k + "' is read but not in the registry");
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

// The sources that handle entities: every engine_ext/ and game/ file naming LevelEntity or MapEntity.
std::vector<std::pair<fs::path, std::string>> entitySources() {
    std::vector<std::pair<fs::path, std::string>> out;
    for (const char* dir : {"engine_ext", "game"})
        for (const auto& entry : fs::recursive_directory_iterator(fs::path(OBSCURA_SOURCE_DIR) / dir)) {
            const auto ext = entry.path().extension();
            if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
            std::string text = readAll(entry.path());
            if (text.find("LevelEntity") == std::string::npos && text.find("MapEntity") == std::string::npos) continue;
            out.emplace_back(entry.path(), std::move(text));
        }
    return out;
}

TEST(EntityReads, EveryClassAndKeyTheSourcesReadIsInTheRegistry) {
    std::vector<std::string> problems;
    std::vector<std::string> scanned;
    for (const auto& [path, text] : entitySources()) {
        scanned.push_back(path.filename().string());
        for (auto& p : unlisted(text, path.string())) problems.push_back(p);
    }
    std::string all;
    for (const auto& p : problems) all += p + "\n";
    EXPECT_TRUE(problems.empty()) << all;
    // The files that read entities today are among those scanned (the scan is not empty by mistake).
    for (const char* f : {"map_compile.cpp", "physics_world.cpp", "combat.cpp", "decal_sign.cpp", "map_lights.cpp", "movers.cpp", "triggers.cpp"})
        EXPECT_NE(std::find(scanned.begin(), scanned.end(), f), scanned.end()) << f;
}

// The other direction: a key the registry (and so the FGD) offers a level designer is read by the
// code, or it is listed here with what it is for.
TEST(EntityReads, EveryRegistryKeyIsReadByTheSources) {
    static const std::map<std::string, std::string> notReadByName = {
        {"_wateralpha", "read as '_' + 'wateralpha' by liquidAlphaKey (map/liquid.cpp)"},
        {"_slimealpha", "as _wateralpha"},
        {"_lavaalpha", "as _wateralpha"},
        {"_telealpha", "as _wateralpha"},
        {"_light", "the light value's other name: map_lights.cpp reads it through valueKey"},
        {"modelscale", "misc_model's scale under its other name: map_compile.cpp reads it through scaleKey"},
        {"sounds", "Quake's sound sets for movers: offered to the editor; the game's synthesised sounds do not follow it yet"},
    };
    std::set<std::string> read;
    for (const auto& [path, text] : entitySources())
        for (const std::string& k : keysRead(text)) read.insert(k);
    std::string problems;
    for (const std::string& k : registryKeys()) {
        const bool implicit = std::find(std::begin(kImplicitKeys), std::end(kImplicitKeys), k) != std::end(kImplicitKeys);
        if (!implicit && !read.count(k) && !notReadByName.count(k)) problems += "key '" + k + "' is in the registry but no source reads it\n";
        if (read.count(k) && notReadByName.count(k)) problems += "key '" + k + "' is read now: take it off the not-read list\n";
    }
    EXPECT_TRUE(problems.empty()) << problems;
}

TEST(EntityReads, TheScanCatchesAnUnlistedClassAndKey) {
    const auto p = unlisted("if (e.classname == \"prop_keg\") v = numberKey(level, e, \"volume\", 1, 0, 2, \"l\");\n"
                            "if (e.classname == \"prop_crate\") w = e.value(\"mass\");",
                            "x.cpp");
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0], "x.cpp: key 'volume' is read but not in the registry");
    EXPECT_EQ(p[1], "x.cpp: class 'prop_keg' is read but not in the registry");
    // The other reader forms: map_lights.cpp's key lists and the sim's EntityKeys.
    const auto q = unlisted("l.cone = k.number({\"_cone\", \"_conewidth\"}, 40, 0, 180);\n"
                            "const double s = keys_.number(e, \"swing\", 0); k.colour({\"_color\"}, c);",
                            "y.cpp");
    ASSERT_EQ(q.size(), 2u);
    EXPECT_EQ(q[0], "y.cpp: key 'swing' is read but not in the registry");
    EXPECT_EQ(q[1], "y.cpp: key '_conewidth' is read but not in the registry");
}

}  // namespace
}  // namespace obscura::map
