// The entity classes Obscura knows: one table, read by the map compiler (which classes are known,
// what their brushes become, which are lights), the load summary (unknown classes by name) and the
// TrenchBroom entity definitions (tools/trenchbroom/obscura.fgd, written from this table by
// writeFgd; tests/map/fgd_test.cpp holds the committed file to it both ways). Plain C++, no OGRE.
//
// Every key listed is one the game reads (grep `value("` in engine_ext/ and game/) or, for the
// Quake movers and triggers (game/sim/movers.h, triggers.h), the standard Quake key a mapper sets
// for them. `classname` and `origin` belong to every entity and are not listed (TrenchBroom writes
// them itself); see kImplicitKeys.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace obscura::map {

enum class EntityKind { Point, Brush };

// What a class is for; the compiler acts on Light and the brush role, the rest documents.
enum class EntityRole {
    World,        // worldspawn: the level's static brushes and level-wide settings
    Geometry,     // brush groups compiled with the world (func_wall, func_detail*, func_group...)
    Mover,        // Quake movers (doors, plats, buttons, trains): moved by the game (game/sim/movers.h)
    Trigger,      // trigger volumes: kept as invisible, non-solid brushes
    PlayerStart,  // where the player spawns
    Light,        // a point light
    Model,        // a placed .mesh with a triangle collider
    Game,         // read by a game system (physics props, targets, painted signs)
    Marker,       // a named point other entities refer to; does nothing by itself
};

// What an entity's brushes become (every class may carry brushes; point classes' count as solid).
enum class BrushRole {
    Solid,     // rendered, block the player, bullets and smoke
    NonSolid,  // rendered, block nothing (func_illusionary)
    Volume,    // neither rendered nor solid (triggers)
};

// Value types, as FGD writes them.
enum class KeyType { String, Integer, Float, Colour, Choices, Flags, TargetSource, TargetDestination };

struct KeyChoice {
    std::string value;  // the key's value ("0", "1"...); for Flags, the bit
    std::string label;
};

struct EntityKey {
    std::string name;
    KeyType type = KeyType::String;
    std::string defaultValue;  // as the game applies it when the key is absent; "" for none
    std::string description;
    std::vector<KeyChoice> choices;  // Choices and Flags only
};

// Keys shared by several classes (an FGD @BaseClass).
struct KeyGroup {
    std::string name;
    std::string description;
    std::vector<EntityKey> keys;
};

struct EntityClass {
    std::string name;
    EntityKind kind = EntityKind::Point;
    EntityRole role = EntityRole::Marker;
    BrushRole brushes = BrushRole::Solid;
    std::string description;            // what it does in Obscura
    std::vector<std::string> bases;     // KeyGroup names, in order
    std::vector<EntityKey> keys;        // its own keys
    std::string editorColour;           // FGD color(r g b), 0..255; "" for the editor's default
    std::string editorSize;             // FGD size(...) of a point class, Quake units; "" for 16^3
};

// Keys of every entity, written by the editor itself: not in any class's list.
inline const char* const kImplicitKeys[] = {"classname", "origin"};

const std::vector<KeyGroup>& keyGroups();
const std::vector<EntityClass>& entityClasses();  // in FGD order (bases first in the file)

const KeyGroup* findKeyGroup(std::string_view name);
const EntityClass* findEntityClass(std::string_view classname);  // nullptr: not a class Obscura knows
bool isKnownClass(std::string_view classname);

// A class's keys with its bases' first (a base's key comes once even if listed twice).
std::vector<EntityKey> allKeys(const EntityClass& c);

const char* toString(EntityKind k);     // "point", "brush"
const char* toString(KeyType t);        // FGD type name: "string", "integer", "float", "color1"...

}  // namespace obscura::map
