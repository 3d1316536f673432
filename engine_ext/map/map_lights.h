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
// Also reads every `env_ambient` into level.ambientAreas (its brushes' box, `ambient`, `blend`);
// one without brushes is skipped with a warning.
void compileLights(Level& level, const std::string& path, std::vector<std::string>* warnings);

// The factor the level's ambient light takes at p (world, metres): 1 outside every area; inside an
// area its scale, across a face (blend > 0) mixed linearly over `blend` metres centred on the face;
// a point up to kAmbientAreaGrace outside a face counts as on it (a room's surfaces lie on the box
// the designer drew over them). Overlapping areas: the darkest. shaders/frame/lighting.frag mirrors
// it (ambientScaleAt).
constexpr double kAmbientAreaGrace = 0.02;  // metres: 2 cm, above the G-buffer depth's rounding at 30 m
double ambientScaleAt(const std::vector<AmbientArea>& areas, const Vec3& p);

}  // namespace obscura::map
