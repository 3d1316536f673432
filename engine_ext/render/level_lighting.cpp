// See level_lighting.h.
#include "render/level_lighting.h"
#include "render/ogre_convert.h"

#include "map/quake_light.h"

#include <Ogre.h>
#include <OgreGpuProgramManager.h>
#include <OgreShadowCameraSetupFocused.h>


namespace obscura::render {

namespace {
// Sun shadow map: 1024^2, focused on the view frustum, keeps wall and pillar shadows crisp at
// play distance; on llvmpipe at 720p the 2048^2 map cost 21 ms a frame, 1024^2 costs 7 ms.
// beyond 50 m (a long firing range) everything counts as lit.
constexpr unsigned kShadowMapSize = 1024;
constexpr float kShadowDistance = 50.0f;
}  // namespace

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
