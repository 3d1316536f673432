// Level-wide lighting constants from worldspawn keys (sun, sky ambient), in plain C++ (no OGRE) so
// they are testable without a GPU and the light bake (engine_ext/lightbake) reads the same values;
// level_lighting.h pushes them into the GLSL programs.
#pragma once

#include "map/level.h"

namespace obscura::render {

struct LevelLightingParams {
    Vec3 sunDirection{0.35, 0.8, 0.45};  // towards the sun, unit
    Vec3 sunColour{0, 0, 0};             // linear RGB
    Vec3 skyAmbient{0.32, 0.35, 0.42};
    Vec3 groundAmbient{0.16, 0.14, 0.12};
    // What the light bake takes of the same keys: the irradiance a face turned up (down) gets from
    // a fully open sky dome, and the `_minlight` floor (0 unless the level sets it).
    Vec3 dome, domeBelow, minlight;
};

// From the worldspawn keys map_lights.cpp read (Level::lighting): the sun (`_sunlight`, its mangle
// and colour, or a `_sun` light), the ambient: Obscura's `_ambient_sky`/`_ambient_ground` as given;
// else, in a level with lights or `_minlight`, `_minlight` (default: a dark floor) plus the sky
// domes `_sunlight2` (from above) and `_sunlight3` (below); else the default hemisphere.
LevelLightingParams computeLevelLighting(const map::Level& level);

}  // namespace obscura::render
