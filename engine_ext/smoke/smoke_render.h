// OGRE glue of the smoke grenades, the frame's volumetrics stage (engine_ext/frame/technique.h):
// each live volume's fields (density, transmittance towards the sun, sky visibility;
// SmokeVolume::exportRGBFloat) uploaded to its own PF_FLOAT32_RGB 3D texture after the simulation
// steps, and ray-marched at half resolution against the G-buffer's depth in the frame's shared
// volumetric pass (frame::kVolumesCompositor, shaders/frame/volumes.frag, shaders/smoke/), lit by the sun, the sky and the level's point
// lights near the smoke; the sun through the level's sun shadow map too (bound here each frame). The frame lays the result (volumeMap) over the light before the tone map.
// Up to 4 lamps (the brightest bound level lamps, then the signs' lamps that reach the smoke) are
// shadowed by the smoke and the walls in its box: their transmittances
// (SmokeVolume::exportLampTransmittance) go to a second, PF_FLOAT32_RGBA 3D texture per volume.
// Textures follow the volumes' ids: made when one appears, dropped when it finishes.
#pragma once

#include "frame/technique.h"
#include "smoke/smoke_manager.h"

#include <OgreTexture.h>
#include <OgreVector.h>

#include <cstdint>
#include <map>
#include <vector>

namespace Ogre {
class SceneManager;
}

namespace obscura::smoke {

class SmokeRender : public frame::Technique {
public:
    SmokeRender();
    ~SmokeRender() override;
    SmokeRender(const SmokeRender&) = delete;
    SmokeRender& operator=(const SmokeRender&) = delete;

    // A point light that can light the smoke: world position, linear colour (as the level's
    // surfaces get it), range in metres (the light reaches zero there: (1 - d / range)^2).
    struct PointLight {
        Ogre::Vector3 position, colour;
        float range;
    };
    // The point lights of the scene (the level's map lights: OGRE LT_POINT lights, read once;
    // the sun is lit separately). Call after the level is built.
    void setLights(Ogre::SceneManager& scene);
    void setLights(std::vector<PointLight> lights) { lights_ = std::move(lights); }
    // The signs' lamps (engine_ext/signs: SignSpec::lamp, lightColour x intensity, range). The
    // signs light their own shafts; here the smoke's transmittance towards them is exported so the
    // shafts are shadowed by the smoke they cross (volumes.frag matches a sign to its channel by
    // the lamp's position).
    void setSignLamps(std::vector<PointLight> lamps) { signLamps_ = std::move(lamps); }

    // Uploads every volume of `manager` when `stepped` (it stepped and computed its transmittance
    // since the last call); `time` is game seconds (the sub-grid noise drifts with it).
    void update(const SmokeManager& manager, bool stepped, float time);
    std::size_t marched() const { return bindings_.size(); }
    std::size_t lightsBound() const { return bound_.size(); }
    std::size_t lampsShadowed() const { return shadowed_.size(); }  // channels of the lamp maps in use
    // Upload cost so far (also logged at exit): seconds exporting (CPU) and blitting into the
    // textures, and volumes uploaded.
    double exportSeconds() const { return exportSeconds_; }
    double uploadSeconds() const { return uploadSeconds_; }
    double lampSeconds() const { return lampSeconds_; }  // exportLampTransmittance and its blit
    std::size_t uploads() const { return uploads_; }

    // frame::Technique
    std::string folder() const override { return "engine_ext/smoke"; }
    frame::Stage stage() const override { return frame::Stage::Volumetrics; }
    std::string compositor() const override;
    std::string missingFeature(const frame::Gpu& gpu) const override;
    void bind(Ogre::uint32 passId, Ogre::Pass& pass, frame::Uniforms& u, const frame::FrameContext& ctx) override;
    std::vector<Output> outputs() const override { return {{"volume", "volumeMap"}}; }

private:
    // A volume to march: its texture, its world box, and the part of it holding smoke.
    struct Binding {
        Ogre::TexturePtr texture, lampTexture;
        Ogre::Vector3 min, size, occupiedMin, occupiedSize;
    };
    void chooseLights();
    void chooseShadowedLamps();
    void uploadLampMaps(const std::vector<std::pair<int, const SmokeVolume*>>& marched);
    void bindSunShadow(Ogre::Pass& pass, frame::Uniforms& u, const Ogre::Camera* camera) const;
    std::map<int, Ogre::TexturePtr> textures_, lampTextures_;  // by volume id
    std::vector<Binding> bindings_;
    std::vector<float> buffer_;
    std::vector<PointLight> lights_, bound_;  // all, and those lighting the smoke now
    std::vector<PointLight> signLamps_;
    std::vector<Ogre::Vector3> shadowed_;      // the lamp maps' channels: bound_'s first ones, then signs'
    std::size_t shadowedLevelLamps_ = 0;       // how many of them are bound_'s (the first)
    std::vector<Vec3> shadowedPositions_;      // shadowed_ for the export
    Ogre::TexturePtr noLampShadow_;  // 1x1x1 (1, 1, 1, 1): nothing between any lamp and the smoke
    Ogre::TexturePtr noVolume_;  // 1x1x1, bound to unused units
    Ogre::TexturePtr noSunShadow_;  // 1x1 PF_FLOAT32_R 1.0 (no caster): bound when there is no sun shadow map
    float sigma_ = 4, time_ = 0;
    double exportSeconds_ = 0, uploadSeconds_ = 0, lampSeconds_ = 0;
    std::size_t uploads_ = 0;
};

}  // namespace obscura::smoke
