// OGRE glue of the smoke grenades, the frame's volumetrics stage (engine_ext/frame/technique.h):
// each live volume's packed fields (density, transmittance towards the sun; SmokeVolume::exportRG8)
// uploaded to its own PF_RG8 3D texture after the simulation steps, and ray-marched at half
// resolution against the G-buffer's depth (media/smoke/smoke.compositor, shaders/smoke/). The
// frame lays the result (volumeMap) over the light before the tone map. Textures follow the
// volumes' ids: made when one appears, dropped when it finishes.
#pragma once

#include "frame/technique.h"
#include "smoke/smoke_manager.h"

#include <OgreTexture.h>
#include <OgreVector.h>

#include <cstdint>
#include <map>
#include <vector>

namespace obscura::smoke {

class SmokeRender : public frame::Technique {
public:
    SmokeRender();
    ~SmokeRender() override;
    SmokeRender(const SmokeRender&) = delete;
    SmokeRender& operator=(const SmokeRender&) = delete;

    // Uploads every volume of `manager` when `stepped` (it stepped and computed its transmittance
    // since the last call); `time` is game seconds (the sub-grid noise drifts with it).
    void update(const SmokeManager& manager, bool stepped, float time);
    std::size_t marched() const { return bindings_.size(); }

    // frame::Technique
    std::string folder() const override { return "engine_ext/smoke"; }
    frame::Stage stage() const override { return frame::Stage::Volumetrics; }
    std::string compositor() const override;
    std::string missingFeature(const frame::Gpu& gpu) const override;
    void bind(Ogre::uint32 passId, Ogre::Pass& pass, frame::Uniforms& u, const frame::FrameContext& ctx) override;
    Output output() const override { return {"volume", "volumeMap"}; }

private:
    // A volume to march: its texture, its world box, and the part of it holding smoke.
    struct Binding {
        Ogre::TexturePtr texture;
        Ogre::Vector3 min, size, occupiedMin, occupiedSize;
    };
    std::map<int, Ogre::TexturePtr> textures_;
    std::vector<Binding> bindings_;
    std::vector<std::uint8_t> buffer_;
    Ogre::TexturePtr noVolume_;  // 1x1x1, bound to unused units
    float densityScale_ = 1, time_ = 0;
};

}  // namespace obscura::smoke
