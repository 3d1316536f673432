// OGRE glue of the back-lit signs (issue 15; the core is sign_light.h): each sign's plate in the
// scene (its letters glow where the lamp shines through, bullet holes too), the letters' distance
// field as a float texture, and two techniques of the frame:
//   shafts()    the volumetrics stage: the lamp's light scattered by the haze and the smoke, in the
//               frame's shared march (frame::kVolumesCompositor, shaders/signs/sign_march.glsl)
//   surfaces()  the lighting stage: the lettered light on floors and walls, added into `lit`
//               (media/signs/signs.compositor, shaders/signs/sign_surfaces.frag)
// Both read the same uniforms (shaders/signs/sign_light.glsl), for the SIGN_MAX_LIGHTS signs
// nearest the camera. The game pushes the holes one way (setHoles); nothing here steps anything.
#pragma once

#include "frame/technique.h"
#include "signs/sign_light.h"

#include <OgreMaterialManager.h>
#include <OgreTexture.h>
#include <OgreVector.h>

#include <memory>
#include <vector>

namespace Ogre {
class Camera;
class SceneManager;
class SceneNode;
class ManualObject;
}  // namespace Ogre

namespace obscura::signs {

// How the signs' light is drawn (`--sign-mode`, the F1 panel). Meshuggah: the seed's rays
// (meshuggah.h) instead of the shafts, the lettered light on surfaces kept, for comparison.
enum class SignMode { Off, Shafts, Meshuggah };
const char* signModeName(SignMode m);

class Meshuggah;

// The plates' visibility flag: kept out of their own lamps' shadow maps.
constexpr unsigned kPlateVisibilityFlag = 1u << 28;

class SignRender : public Ogre::MaterialManager::Listener {
public:
    // One plate per sign (masks[i] is specs[i]'s); `haze`: the haze's scattering, per metre;
    // `shadowExclude`: visibility flags kept out of the lamps' shadow maps (sky, translucent liquids).
    SignRender(Ogre::SceneManager& scene, std::vector<SignSpec> specs, std::vector<SignMask> masks, float haze,
               Ogre::uint32 shadowExclude);
    ~SignRender() override;
    SignRender(const SignRender&) = delete;
    SignRender& operator=(const SignRender&) = delete;

    // Once a frame, before the frame updates: the holes (when `version` moved) and which signs
    // are lit: those whose beam is in `view`'s frustum, the nearest.
    void update(const std::vector<SignHoles>& holes, std::uint64_t version, const Ogre::Camera& view);
    std::size_t litCount() const { return chosen_.size(); }
    void setMode(SignMode mode) { mode_ = mode; }
    SignMode mode() const { return mode_; }
    void setHaze(float haze) { haze_ = haze; }
    std::size_t signCount() const { return specs_.size(); }

    frame::Technique& shafts();
    // The shadow caster for the SignShadow scheme (Ogre::MaterialManager::Listener).
    Ogre::Technique* handleSchemeNotFound(unsigned short, const Ogre::String& schemeName, Ogre::Material*, unsigned short,
                                          const Ogre::Renderable*) override;
    frame::Technique& surfaces();
    // The Meshuggah mode's ray materials, for Frame::addSceneMaterial (they read gbufferDepth).
    const std::vector<Ogre::MaterialPtr>& meshuggahMaterials() const;

private:
    class Shafts;
    class Surfaces;
    // Sets sign_light.glsl's uniforms and textures for the chosen signs.
    void bindSigns(Ogre::Pass& pass, frame::Uniforms& u) const;
    void buildPlate(std::size_t i);
    void updatePlate(std::size_t i);
    void drawShadow(std::size_t slot);

    // A lamp's shadow map: a camera at the lamp through its plate's rectangle.
    struct Shadow {
        Ogre::TexturePtr texture;
        Ogre::Camera* camera = nullptr;
        Ogre::SceneNode* node = nullptr;
        Ogre::Matrix4 worldToClip;
    };

    Ogre::SceneManager& scene_;
    std::vector<SignSpec> specs_;
    std::vector<SignMask> masks_;
    std::vector<std::vector<Hole>> holes_;
    std::vector<Ogre::TexturePtr> maskTextures_;
    std::vector<Ogre::MaterialPtr> plateMaterials_;
    std::vector<Ogre::SceneNode*> nodes_;
    std::vector<Ogre::ManualObject*> plates_;
    std::vector<std::size_t> chosen_;  // the signs lit this frame, nearest first
    std::vector<Vec3> beamLo_, beamHi_;  // each sign's beamBounds (sign_light.h)
    Ogre::TexturePtr noMask_, noShadow_;
    std::vector<Shadow> shadows_;  // SIGN_MAX_LIGHTS slots, for chosen_
    Ogre::MaterialPtr caster_;
    Ogre::uint32 shadowExclude_;
    std::uint64_t holesVersion_ = ~0ull;
    SignMode mode_ = SignMode::Shafts;
    float haze_;
    std::unique_ptr<Shafts> shafts_;
    std::unique_ptr<Surfaces> surfaces_;
    std::unique_ptr<Meshuggah> meshuggah_;  // SignMode::Meshuggah's rays (meshuggah.h)
};

}  // namespace obscura::signs
