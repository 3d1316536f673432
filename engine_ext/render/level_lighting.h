// Level-wide lighting constants (render/level_light_params.h) pushed into the GLSL programs through
// OGRE shared parameters (media/materials/level.program), and the sun's shadow map.
#pragma once

#include "map/level.h"
#include "render/level_light_params.h"

namespace Ogre {
class Light;
class SceneManager;
}  // namespace Ogre

namespace obscura::render {

// Sets the shared parameters ObscuraLighting (sunDirection, sunColour, skyAmbient, groundAmbient)
// that the level and shadow-caster programs reference.
void applyLevelLighting(const map::Level& level);

// Turns on the sun's shadow map (OGRE integrated texture shadows, one 1024^2 float texture
// focused on the view frustum) and adds the sun as a shadow-casting directional light.
// Returns the light (owned by the scene manager), or null when the level has no sun.
Ogre::Light* createSun(Ogre::SceneManager& scene, const map::Level& level);

}  // namespace obscura::render
