// Level-wide lighting constants from worldspawn keys (sun, sky ambient), pushed into the
// GLSL programs through OGRE shared parameters (media/materials/level.program). The values themselves are computed in plain C++
// (computeLevelLighting) so they are testable without a GPU.
#pragma once

#include "map/level.h"

namespace Ogre {
class Light;
class SceneManager;
}  // namespace Ogre

namespace obscura::render {

struct LevelLightingParams {
    Vec3 sunDirection{0.35, 0.8, 0.45};  // towards the sun, unit
    Vec3 sunColour{0, 0, 0};             // linear RGB
    Vec3 skyAmbient{0.32, 0.35, 0.42};
    Vec3 groundAmbient{0.16, 0.14, 0.12};
};

// From the worldspawn keys map_lights.cpp read (Level::lighting): the sun (`_sunlight`, its mangle
// and colour, or a `_sun` light), the ambient: Obscura's `_ambient_sky`/`_ambient_ground` as given;
// else, in a level with lights or `_minlight`, `_minlight` (default: a dark floor) plus the sky
// domes `_sunlight2` (from above) and `_sunlight3` (below); else the default hemisphere.
LevelLightingParams computeLevelLighting(const map::Level& level);

// Sets the shared parameters ObscuraLighting (sunDirection, sunColour, skyAmbient, groundAmbient)
// that the level and shadow-caster programs reference.
void applyLevelLighting(const map::Level& level);

// Turns on the sun's shadow map (OGRE integrated texture shadows, one 1024^2 float texture
// focused on the view frustum) and adds the sun as a shadow-casting directional light.
// Returns the light (owned by the scene manager), or null when the level has no sun.
Ogre::Light* createSun(Ogre::SceneManager& scene, const map::Level& level);

}  // namespace obscura::render
