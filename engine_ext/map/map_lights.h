// Light entities and worldspawn lighting keys -> Level::lights and Level::lighting (plain C++).
// Which keys mean what is listed in engine_ext/map/README.md ("Lighting keys").
#pragma once

#include "map/level.h"

#include <string>
#include <vector>

namespace obscura::map {

// Reads every `light*` entity and worldspawn's lighting keys of `level.entities` (already compiled:
// origins in metres). Malformed keys warn with `path:line` and fall back; a light value beyond
// +-kMaxLightValue throws MapError (as before).
void compileLights(Level& level, const std::string& path, std::vector<std::string>* warnings);

}  // namespace obscura::map
