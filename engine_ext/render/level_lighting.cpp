// See level_lighting.h.
#include "render/level_lighting.h"
#include "render/ogre_convert.h"

#include "map/quake_light.h"

#include <Ogre.h>
#include <OgreGpuProgramManager.h>
#include <OgreShadowCameraSetupFocused.h>


namespace obscura::render {

namespace {
// Quake light values, `_sunlight` included, share one scale (map/quake_light.h): 200 maps to a sun
// of colour 1.0, which with the tone map gives a bright but unclipped wall.
constexpr double kSunlightUnit = map::kQuakeLightUnit;
// `_sunlight2` (the sky dome) of 150 gives an ambient of about 0.4 from above.
constexpr double kSkyDomeUnit = 375.0;
// The ambient of a level that places lights but sets no `_minlight`: Quake's is 0; this floor (two
// light units) keeps unlit corners a dark shape for the AO to work on (about 28/255 on a mid-grey
// wall after the tone map) instead of flat black.
constexpr double kLitLevelAmbient = 0.01;
// Sun shadow map: 1024^2, focused on the view frustum, keeps wall and pillar shadows crisp at
// play distance; on llvmpipe at 720p the 2048^2 map cost 21 ms a frame, 1024^2 costs 7 ms.
// beyond 50 m (a long firing range) everything counts as lit.
constexpr unsigned kShadowMapSize = 1024;
constexpr float kShadowDistance = 50.0f;
}  // namespace

LevelLightingParams computeLevelLighting(const map::Level& level) {
    LevelLightingParams p;
    const map::LevelLightingKeys& k = level.lighting;
    if (k.sunlight > 0) {
        p.sunDirection = normalize(-k.sunTravel);
        p.sunColour = k.sunColour * (k.sunlight / kSunlightUnit);
    }
    const Vec3 dome = k.domeColour * (k.dome / kSkyDomeUnit), domeBelow = k.domeBelowColour * (k.domeBelow / kSkyDomeUnit);
    if (k.hasAmbient) {
        // Obscura's own hemisphere keys: the ambient as given (the arena keeps its look through them).
        p.skyAmbient = k.ambientSky;
        p.groundAmbient = k.ambientGround;
    } else if (k.hasMinlight || k.hasLightEntities) {
        // Quake's ambient: `_minlight` (else the dark floor) from everywhere, plus the sky domes.
        const Vec3 floor = k.hasMinlight ? k.minlightColour * (k.minlight / map::kQuakeLightUnit)
                                         : Vec3{kLitLevelAmbient, kLitLevelAmbient, kLitLevelAmbient};
        p.skyAmbient = floor + dome;
        p.groundAmbient = floor + domeBelow;
    } else if (k.dome > 0) {
        // A level without lights or ambient keys keeps the default hemisphere, half of it under a dome.
        p.skyAmbient = dome + p.skyAmbient * 0.5;
        p.groundAmbient = p.groundAmbient + domeBelow;
    }
    return p;
}

void applyLevelLighting(const map::Level& level) {
    const LevelLightingParams p = computeLevelLighting(level);
    auto& gpm = Ogre::GpuProgramManager::getSingleton();
    const auto& all = gpm.getAvailableSharedParameters();
    if (all.find("ObscuraLighting") == all.end())
        throw std::runtime_error("shared_params ObscuraLighting is missing (media/materials/level.program)");
    Ogre::GpuSharedParametersPtr params = gpm.getSharedParameters("ObscuraLighting");
    params->setNamedConstant("sunDirection", toOgre(p.sunDirection));
    params->setNamedConstant("sunColour", toOgre(p.sunColour));
    params->setNamedConstant("skyAmbient", toOgre(p.skyAmbient));
    params->setNamedConstant("groundAmbient", toOgre(p.groundAmbient));
}

}  // namespace obscura::render

namespace obscura::render {

Ogre::Light* createSun(Ogre::SceneManager& scene, const map::Level& level) {
    const LevelLightingParams p = computeLevelLighting(level);
    if (dot(p.sunColour, p.sunColour) <= 0) return nullptr;
    scene.setShadowTechnique(Ogre::SHADOWTYPE_TEXTURE_ADDITIVE_INTEGRATED);
    scene.setShadowTextureSettings(kShadowMapSize, 1, Ogre::PF_FLOAT32_R);
    scene.setShadowTextureCasterMaterial(Ogre::MaterialManager::getSingleton().getByName("Obscura/ShadowCaster"));
    scene.setShadowTextureSelfShadow(true);
    scene.setShadowFarDistance(kShadowDistance);
    scene.setShadowCameraSetup(std::make_shared<Ogre::FocusedShadowCameraSetup>());
    Ogre::Light* sun = scene.createLight("Sun");
    sun->setType(Ogre::Light::LT_DIRECTIONAL);
    // The colour lives in the level shader's uniforms; OGRE's copy only has to be non-black.
    sun->setDiffuseColour(Ogre::ColourValue::White);
    sun->setSpecularColour(Ogre::ColourValue::Black);
    sun->setCastShadows(true);
    auto* node = scene.getRootSceneNode()->createChildSceneNode();
    node->setDirection(toOgre(-p.sunDirection), Ogre::Node::TS_WORLD);
    node->attachObject(sun);
    return sun;
}

}  // namespace obscura::render
