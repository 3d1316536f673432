// OGRE glue of the smoke grenades, the frame's volumetrics stage (engine_ext/frame/technique.h):
// each marched volume's fields (density, transmittance towards the sun, sky visibility;
// SmokeVolume::exportRGBFloat, exported on the smoke's worker: smoke_pipeline.h) uploaded to its
// own PF_FLOAT32_RGB 3D texture when the worker published a step, and ray-marched at half resolution against the G-buffer's depth in the frame's shared
// volumetric pass (frame::kVolumesCompositor, shaders/frame/volumes.frag, shaders/smoke/), lit by the sun, the sky and the level's point
// lights near the smoke; the sun through the level's sun shadow map too (bound here each frame). The frame lays the result (volumeMap) over the light before the tone map.
// Up to 4 lamps (the brightest bound level lamps, then the signs' lamps that reach the smoke;
// smoke_lamps.h) are shadowed by the smoke and the walls in its box: their transmittances
// (SmokeVolume::exportLampTransmittance) go to a second, PF_FLOAT32_RGBA 3D texture per volume.
// The bound lamps' light, computed on the grid by the worker (smoke_lamp_light.h), goes to one
// PF_FLOAT32_RGBA atlas all volumes share, two slabs each.
// Textures follow the volumes' ids: made when one appears, dropped when it finishes.
#pragma once

#include "frame/technique.h"
#include "smoke/smoke_pipeline.h"

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

    // Uploads the frame's volumes (the smoke's worker exported them: smoke/smoke_pipeline.h) when
    // its version changed; `time` is game seconds (the sub-grid noise drifts with it), `sigma` the
    // solver's shadowSigma (the march's extinction). The render thread's part of the smoke: blits.
    void update(const SmokeFrame& frame, float time, float sigma);
    // After update(), once a frame: whether the march needs the smoke now: a marched box in the
    // view frustum, or `shadowing` (another medium is marched this frame: the signs' shafts read
    // the smoke's lamp maps). A cloud out of view then costs no volumetric pass (issue 31).
    void cull(const Ogre::Camera& view, bool shadowing);
    std::size_t marched() const { return bindings_.size(); }
    std::size_t lightsBound() const { return lamps_.bound.size(); }
    std::size_t lampsShadowed() const { return lamps_.shadowed.size(); }  // channels of the lamp maps in use
    // Upload cost so far (also logged at exit, beside the worker's export and lamp maps): seconds
    // blitting into the textures on the render thread, and volumes uploaded; the last update's.
    double uploadSeconds() const { return uploadSeconds_; }
    std::size_t uploads() const { return uploads_; }
    double lastUpdateMs() const { return lastUpdateMs_; }

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
    Ogre::TexturePtr textureFor(std::map<int, Ogre::TexturePtr>& cache, std::map<int, Ogre::TexturePtr>& live, int id,
                                const GridInfo& g, Ogre::PixelFormat format, const std::string& prefix);
    void uploadLampLight(std::size_t slot, const GridInfo& g, const std::vector<float>& light);
    void bindSunShadow(Ogre::Pass& pass, frame::Uniforms& u, const Ogre::Camera* camera) const;
    std::map<int, Ogre::TexturePtr> textures_, lampTextures_;  // by volume id
    std::vector<Binding> bindings_;
    bool inView_ = true;  // cull()
    LampChoice lamps_;  // those lighting the smoke now (the worker chose them: smoke_lamps.h)
    Ogre::TexturePtr noLampShadow_;  // 1x1x1 (1, 1, 1, 1): nothing between any lamp and the smoke
    Ogre::TexturePtr lampLight_;  // the lamps' light of every marched volume: two slabs each (uploadLampLight)
    Ogre::TexturePtr noLampLight_;  // 1x1x1 (0, 0, 0, 0): no lamp lights the smoke
    Ogre::TexturePtr noVolume_;  // 1x1x1, bound to unused units
    Ogre::TexturePtr noSunShadow_;  // 1x1 PF_FLOAT32_R 1.0 (no caster): bound when there is no sun shadow map
    float sigma_ = 4, time_ = 0;
    std::uint64_t uploadedVersion_ = 0;
    double exportMs_ = 0, lampMs_ = 0, uploadSeconds_ = 0, lastUpdateMs_ = 0;  // the worker's, the blits'
    std::size_t uploads_ = 0;
    std::vector<double> workerMs_;  // SmokeFrame's step + light + export + lamp ms, a published step
};

}  // namespace obscura::smoke
