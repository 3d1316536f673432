// See level_lighting.h.
#include "render/level_lighting.h"
#include "render/ogre_convert.h"

#include <Ogre.h>
#include <OgreGpuProgramManager.h>
#include <OgreShadowCameraSetupFocused.h>

#include <cmath>
#include <sstream>

namespace obscura::render {

namespace {
constexpr double kPi = 3.14159265358979323846;
// ericw-tools' default `_sunlight` is 0 (off); a typical outdoor map uses 100-300. 200 maps to a
// sun of colour 1.0, which with the tone map in level.frag gives a bright but unclipped wall.
constexpr double kSunlightUnit = 200.0;
// `_sunlight2` (the sky dome) of 150 gives an ambient of about 0.4 from above.
constexpr double kSkyDomeUnit = 375.0;
// Sun shadow map: 1024^2, focused on the view frustum, keeps wall and pillar shadows crisp at
// play distance; on llvmpipe at 720p the 2048^2 map cost 21 ms a frame, 1024^2 costs 7 ms.
// beyond 50 m (a long firing range) everything counts as lit.
constexpr unsigned kShadowMapSize = 1024;
constexpr float kShadowDistance = 50.0f;

Vec3 parseVec(const std::string& s, const Vec3& fallback) {
    std::istringstream is(s);
    Vec3 v;
    if (!(is >> v.x >> v.y >> v.z)) return fallback;
    return v;
}

Vec3 parseColour(const std::string& s) {
    Vec3 c = parseVec(s, {1, 1, 1});
    if (c.x > 1 || c.y > 1 || c.z > 1) c = c / 255.0;
    return c;
}

}  // namespace

LevelLightingParams computeLevelLighting(const map::Level& level) {
    LevelLightingParams p;
    if (level.entities.empty()) return p;
    const map::LevelEntity& world = level.entities.front();
    const double sun = std::atof(world.value("_sunlight", "0").c_str());
    if (sun > 0) {
        // Default straight down, as in ericw-tools.
        const Vec3 mangle = parseVec(world.value("_sun_mangle", "0 -90 0"), {0, -90, 0});
        const double yaw = mangle.x * kPi / 180.0, pitch = mangle.y * kPi / 180.0;
        // Direction the light travels, in Quake axes, converted to Y-up: (x, z, -y).
        const Vec3 travelQ{std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)};
        p.sunDirection = normalize(-Vec3{travelQ.x, travelQ.z, -travelQ.y});
        p.sunColour = parseColour(world.value("_sunlight_color", "255 255 255")) * (sun / kSunlightUnit);
    }
    const double dome = std::atof(world.value("_sunlight2", "0").c_str());
    if (dome > 0) {
        const Vec3 c = parseColour(world.value("_sunlight2_color", "255 255 255"));
        p.skyAmbient = c * (dome / kSkyDomeUnit) + p.skyAmbient * 0.5;
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
