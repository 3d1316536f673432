// The AO modes as the frame's AO stage (engine_ext/frame/technique.h): names the mode's
// compositor (media/ssao/ssao.compositor) to the frame, makes its own textures (the per-pixel
// rotations, the level's top-down height map for the heightfield mode), sets its buffers'
// resolution and its uniforms. The G-buffer it reads and the light it darkens are the frame's.
#pragma once

#include "frame/technique.h"

#include <OgreMaterialManager.h>
#include <OgreMatrix4.h>
#include <OgreTexture.h>

#include <cstdint>
#include <string>
#include <vector>

namespace Ogre {
class AxisAlignedBox;
class SceneManager;
}  // namespace Ogre

namespace obscura::ssao {

struct AoKnobs {
    double radius = 0.6;   // ssao_knobs.h
    double largeRadius = 2.0;  // the combined mode's large scale
    double intensity = 2.0;
    int samples = 16;
    double resolution = 0.25;  // AO computed at this fraction of the width and height (1, 0.5, 0.25)
};

class AmbientOcclusion : public frame::Technique, public Ogre::MaterialManager::Listener {
public:
    explicit AmbientOcclusion(std::uint64_t seed);
    ~AmbientOcclusion() override;
    AmbientOcclusion(const AmbientOcclusion&) = delete;
    AmbientOcclusion& operator=(const AmbientOcclusion&) = delete;

    // "off" or one of modeNames(); the frame picks it up at its next update.
    void setMode(const std::string& mode) { mode_ = mode; }
    const std::string& mode() const { return mode_; }
    void setKnobs(const AoKnobs& k) { knobs_ = k; }
    // Renders the level's top-down height map for the heightfield mode: the highest surface over
    // each spot of `bounds` (world space), leaving out objects whose visibility flags are all in
    // `excludeFlags` (the sky). Call once the level is built; until then heightfield = horizon.
    void buildHeightMap(Ogre::SceneManager& scene, const Ogre::AxisAlignedBox& bounds, Ogre::uint32 excludeFlags);

    // frame::Technique
    std::string folder() const override { return "engine_ext/ssao"; }
    frame::Stage stage() const override { return frame::Stage::AO; }
    std::string compositor() const override;
    std::string configuration() const override;
    std::string missingFeature(const frame::Gpu& gpu) const override;
    void configure(Ogre::CompositionTechnique& t) const override;
    void setup(Ogre::uint32 passId, Ogre::Pass& pass) override;
    void bind(Ogre::uint32 passId, Ogre::Pass& pass, frame::Uniforms& u, const frame::FrameContext& ctx) override;
    std::vector<Output> outputs() const override { return {{"blurY", "aoMap"}}; }

    // Ogre::MaterialManager::Listener: the height map's scheme for every material.
    Ogre::Technique* handleSchemeNotFound(unsigned short schemeIndex, const Ogre::String& schemeName,
                                          Ogre::Material* originalMaterial, unsigned short lodIndex,
                                          const Ogre::Renderable* rend) override;

private:
    Ogre::TexturePtr noise_, heightMap_;
    Ogre::MaterialPtr heightMaterial_;
    Ogre::Matrix4 heightViewProj_ = Ogre::Matrix4::IDENTITY;
    int heightMapVersion_ = 0;  // a new map re-binds the heightfield pass
    // [n - 1]: the kernel relaxed for n samples, SSAO_MAX_SAMPLES x vec3 (zero-padded).
    std::vector<std::vector<float>> hemisphereKernels_, sphereKernels_;
    std::string mode_ = "off";
    AoKnobs knobs_;
};

}  // namespace obscura::ssao
