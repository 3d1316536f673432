// The entity-class registry and what the compiler does with it: known and unknown classes (counted
// by name), brush roles, lights, and Quake 2's named player starts.
#include <gtest/gtest.h>

#include "map/entity_classes.h"
#include "map/map_compile.h"
#include "test_maps.h"

#include <optional>
#include <set>

namespace obscura::map {
namespace {
using testdata::cube;
using testdata::entity;

using testdata::compile;

TEST(EntityClasses, NamesAreUniqueAndEveryBaseExists) {
    std::set<std::string> names;
    for (const EntityClass& c : entityClasses()) {
        EXPECT_TRUE(names.insert(c.name).second) << c.name << " listed twice";
        EXPECT_FALSE(c.description.empty()) << c.name;
        for (const std::string& b : c.bases) EXPECT_NE(findKeyGroup(b), nullptr) << c.name << "'s base " << b;
        std::set<std::string> keys;
        for (const EntityKey& k : allKeys(c)) {
            EXPECT_TRUE(keys.insert(k.name).second) << c.name << " key " << k.name << " twice";
            for (const char* implicit : kImplicitKeys) EXPECT_NE(k.name, implicit) << c.name;
            EXPECT_EQ(k.choices.empty(), k.type != KeyType::Choices && k.type != KeyType::Flags) << c.name << " " << k.name;
        }
    }
}

TEST(EntityClasses, EveryClassTheGameReadsIsKnown) {
    // The classes engine_ext/ and game/ look for by name, and the Quake classes the brief lists.
    for (const char* c : {"worldspawn", "info_player_start", "info_player_deathmatch", "info_player_coop", "light",
                          "light_flame_small_yellow", "misc_model", "prop_crate", "prop_barrel", "target_popup", "target_moving",
                          "decal_sign", "light_sign", "info_sign", "func_door", "func_door_secret", "func_plat", "func_button", "func_train",
                          "path_corner", "trigger_multiple", "trigger_once", "trigger_teleport", "trigger_push",
                          "info_teleport_destination", "func_wall", "func_illusionary", "func_detail", "func_detail_wall",
                          "func_detail_illusionary", "func_group"})
        EXPECT_TRUE(isKnownClass(c)) << c;
    for (const char* c : {"monster_ogre", "func_", "trigger_", "light_", "lightning", "prop_", "target_", "", "smoke_volume"})
        EXPECT_FALSE(isKnownClass(c)) << c;  // no prefix matches any more
}

TEST(EntityClasses, KeysTheGameReadsAreListedWithTheirDefaults) {
    const auto keyOf = [](const char* cls, const char* name) -> std::optional<EntityKey> {
        for (const EntityKey& k : allKeys(*findEntityClass(cls)))
            if (k.name == name) return k;
        return std::nullopt;
    };
    const struct {
        const char *cls, *key, *def;
    } expected[] = {{"prop_crate", "size", "0.75"},       {"prop_crate", "mass", "20"},        {"prop_barrel", "radius", "0.3"},
                    {"target_popup", "reset", "3"},       {"target_moving", "distance", "6"}, {"light", "light", "300"},
                    {"worldspawn", "units_per_metre", "32"}, {"decal_sign", "depth", "0.2"},  {"func_door", "lip", "8"},
                    {"info_player_start", "targetname", ""}, {"misc_model", "scale", "1"}};
    for (const auto& e : expected) {
        const std::optional<EntityKey> k = keyOf(e.cls, e.key);
        ASSERT_TRUE(k) << e.cls << " " << e.key;
        EXPECT_EQ(k->defaultValue, e.def) << e.cls << " " << e.key;
    }
}

TEST(EntityClasses, UnknownClassesAreCountedByName) {
    const std::string text = entity("\"classname\" \"worldspawn\"", cube(0, 0, 0)) +
                             entity("\"classname\" \"monster_army\"\n\"origin\" \"0 0 0\"") +
                             entity("\"classname\" \"item_health\"\n\"origin\" \"0 0 0\"") +
                             entity("\"classname\" \"monster_army\"\n\"origin\" \"8 0 0\"") +
                             entity("\"classname\" \"monster_army\"\n\"origin\" \"9 0 0\"") +
                             entity("\"classname\" \"func_door\"", cube(100, 0, 0));
    const Level l = compile(text);
    ASSERT_EQ(l.unknownClassnames, (std::vector<std::string>{"monster_army", "item_health"}));
    EXPECT_EQ(l.unknownClassCounts, (std::vector<int>{3, 1}));
}

TEST(EntityClasses, BrushRolesComeFromTheTableAndUnknownBrushEntitiesFollowQuake) {
    const std::string text = entity("\"classname\" \"worldspawn\"", cube(0, 0, 0)) +
                             entity("\"classname\" \"func_door\"", cube(100, 0, 0)) +            // mover: solid
                             entity("\"classname\" \"trigger_push\"", cube(200, 0, 0)) +         // volume
                             entity("\"classname\" \"func_detail_illusionary\"", cube(300, 0, 0)) +
                             entity("\"classname\" \"trigger_fog\"", cube(400, 0, 0)) +          // unknown trigger_: volume
                             entity("\"classname\" \"func_rotate_door\"", cube(500, 0, 0));      // unknown func_: solid
    const Level l = compile(text);
    ASSERT_EQ(l.brushes.size(), 6u);
    EXPECT_TRUE(l.brushes[1].solid && l.brushes[1].visible);
    EXPECT_TRUE(!l.brushes[2].solid && !l.brushes[2].visible);
    EXPECT_TRUE(!l.brushes[3].solid && l.brushes[3].visible);
    EXPECT_TRUE(!l.brushes[4].solid && !l.brushes[4].visible);
    EXPECT_TRUE(l.brushes[5].solid && l.brushes[5].visible);
    EXPECT_EQ(l.unknownClassnames, (std::vector<std::string>{"trigger_fog", "func_rotate_door"}));
}

TEST(EntityClasses, OnlyTheTablesLightClassesAreLights) {
    const std::string text = entity("\"classname\" \"worldspawn\"", cube(0, 0, 0)) +
                             entity("\"classname\" \"light_globe\"\n\"origin\" \"0 0 0\"") +
                             entity("\"classname\" \"lightning_rod\"\n\"origin\" \"0 0 0\"");  // once a light by its prefix
    const Level l = compile(text);
    EXPECT_EQ(l.lights.size(), 1u);
    EXPECT_EQ(l.unknownClassnames, (std::vector<std::string>{"lightning_rod"}));
}

TEST(EntityClasses, Quake2NamedStartLosesToTheUnnamedOne) {
    // Quake 2: a start with a targetname is where a level transition lands; a fresh start uses the
    // one without. The named one comes first in the file and would have won before.
    const std::string text = entity("\"classname\" \"worldspawn\"", cube(0, 0, 0)) +
                             entity("\"classname\" \"info_player_start\"\n\"targetname\" \"from_base2\"\n\"origin\" \"320 0 24\"") +
                             entity("\"classname\" \"info_player_deathmatch\"\n\"origin\" \"640 0 24\"") +
                             entity("\"classname\" \"info_player_start\"\n\"origin\" \"32 0 24\"");
    const Level l = compile(text);
    ASSERT_TRUE(l.hasPlayerStart);
    EXPECT_DOUBLE_EQ(l.playerStart.x, 1.0);  // 32 units

    // With only named starts the first named one is used, and it still beats deathmatch.
    const std::string named = entity("\"classname\" \"worldspawn\"", cube(0, 0, 0)) +
                              entity("\"classname\" \"info_player_deathmatch\"\n\"origin\" \"640 0 24\"") +
                              entity("\"classname\" \"info_player_start\"\n\"targetname\" \"a\"\n\"origin\" \"320 0 24\"") +
                              entity("\"classname\" \"info_player_start\"\n\"targetname\" \"b\"\n\"origin\" \"96 0 24\"");
    const Level n = compile(named);
    EXPECT_DOUBLE_EQ(n.playerStart.x, 10.0);  // 320 units
}

}  // namespace
}  // namespace obscura::map
