// .map -> Level: brushes become polygons in metres / Y-up, entities become player start, lights,
// models and game objects (see level.h for the conventions, README.md for the entity classes).
#pragma once

#include "map/level.h"
#include "map/map_parser.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace obscura::map {

struct CompileOptions {
    double unitsPerMetre = 0;  // 0: worldspawn "units_per_metre", else 32 (Quake's player is 56 units ~ 1.75 m)
    // Texture size in texels, to turn texel coordinates into repeats; 64x64 when unset (the most
    // common Quake texture size: the generated textures are drawn for that scale).
    std::function<std::pair<int, int>(const std::string&)> textureSize;
};

Level compileLevel(const MapFile& map, const CompileOptions& options = {}, std::vector<std::string>* warnings = nullptr);
Level loadLevel(const std::string& path, const CompileOptions& options = {}, std::vector<std::string>* warnings = nullptr);

// Texture classes (case-insensitive), exposed for tests and other systems.
bool isInvisibleTexture(const std::string& texture);  // clip, trigger, skip, hint, nodraw, caulk, common/*
bool isLiquidTexture(const std::string& texture);     // *water, *lava, *slime, *tele...

}  // namespace obscura::map
