// .map -> Level: brushes become polygons in metres / Y-up, entities become player start, lights,
// models and game objects (see level.h for the conventions, README.md for the entity classes).
#pragma once

#include "map/level.h"
#include "map/map_parser.h"
#include "map/spawnflags.h"

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace obscura::map {

// Ranges a level must keep (outside them compileLevel throws MapError naming file and line):
// units per metre (worldspawn `units_per_metre` or the option) from 1 to 1024 (Quake's 32 with room
// both ways; below 1 a +-262144-unit map reaches 262 km, where floats lose the centimetre);
constexpr double kMinUnitsPerMetre = 1, kMaxUnitsPerMetre = 1024;
// misc_model `scale`/`modelscale` from 1/1000 to 1000 (OGRE divides by it; 0 or 1e39 would assert);
constexpr double kMinModelScale = 1e-3, kMaxModelScale = 1e3;
constexpr std::size_t kMaxModelName = 255;  // misc_model `model` characters (a file name's limit)
// a light's `light`/`_light` value within +-1e6 (its radius follows it; Quake maps use up to ~10^4);
constexpr double kMaxLightValue = 1e6;
// every entity origin inside the brushes' box grown by this many metres on each side.
constexpr double kPlacementMargin = 100;

struct CompileOptions {
    int skill = kDefaultSkill;  // kMinSkill..kMaxSkill (spawnflags.h): entities whose spawnflags exclude it are not compiled
    double unitsPerMetre = 0;  // 0: worldspawn "units_per_metre", else 32 (Quake's player is 56 units ~ 1.75 m); else 1..1024
    // Texture size in texels, to turn texel coordinates into repeats; 64x64 when unset (the most
    // common Quake texture size: the generated textures are drawn for that scale).
    std::function<std::pair<int, int>(const std::string&)> textureSize;
};

// The box placed things must lie in: the brushes' box grown by kPlacementMargin on each side (a
// level of models alone: the margin around the origin). compileLevel holds every entity origin to
// it; the game holds --start-pose, a replay's start and --smoke-at to it (settings checkInLevel).
Aabb placementRegion(const Level& level);
bool inside(const Aabb& box, const Vec3& p);

Level compileLevel(const MapFile& map, const CompileOptions& options = {}, std::vector<std::string>* warnings = nullptr);

// Obscura's own entities for a level nobody here may edit (a real Quake map): the point entities
// of `overlayPath` (.map syntax, entity blocks only, e.g. `e3m4.ent` beside the game's levels)
// appended to `map`'s, each remembering its file for messages. Throws MapError naming the overlay's
// file and line for a malformed file, a worldspawn or an entity with brushes.
void addEntityOverlay(MapFile& map, const std::string& overlayPath);
Level loadLevel(const std::string& path, const CompileOptions& options = {}, std::vector<std::string>* warnings = nullptr);

// Texture classes (case-insensitive), exposed for tests and other systems.
bool isInvisibleTexture(const std::string& texture);  // a tool texture by name (surface_rules.h's toolSurface)
bool isLiquidTexture(const std::string& texture);     // *water, *lava, *slime, *tele...
// Moving brush entities: func_door, func_door_secret, func_plat, func_button, func_train.
bool isMoverClass(const std::string& classname);

}  // namespace obscura::map
