// OGRE glue of the AO modes: installs the GBuffer material scheme (every material gets the
// G-buffer technique without edits), the per-pixel noise texture, the kernel and the level's
// top-down height map (heightfield mode), and switches the compositor chain on a viewport when the
// mode changes. Knob values come from the game. The chain's composite is also where the smoke
// grenades' volumes are ray-marched against the scene depth (setVolumes): with AO off and smoke
// present the chain runs without its AO passes.
#pragma once

#include <OgreCompositorInstance.h>
#include <OgreMaterialManager.h>
#include <OgreTexture.h>

#include <cstdint>
#include <string>
#include <vector>

namespace Ogre {
class AxisAlignedBox;
class Camera;
class SceneManager;
class Viewport;
}  // namespace Ogre

namespace obscura::ssao {

// A ray-marched volume (a smoke grenade's density and transmittance, RG) and its world box.
struct VolumeBinding {
    Ogre::TexturePtr texture;  // TEX_TYPE_3D
    Ogre::Vector3 min, size;   // the texture's world box
    Ogre::Vector3 occupiedMin, occupiedSize;  // where it holds anything: rays are marched only there
};

struct AoKnobs {
    double radius = 0.6;      // metres: about a hand's span, where contact shadows read
    double intensity = 2.0;   // see game/settings.h
    int samples = 16;         // 16: the seeds' 10-16, at half resolution
    double resolution = 0.25;  // AO computed at this fraction of the width and height (1, 0.5, 0.25), blurred, upsampled
};

class AmbientOcclusion : public Ogre::CompositorInstance::Listener, public Ogre::MaterialManager::Listener {
public:
    AmbientOcclusion(Ogre::Viewport& viewport, Ogre::Camera& camera, std::uint64_t seed);
    ~AmbientOcclusion() override;
    AmbientOcclusion(const AmbientOcclusion&) = delete;
    AmbientOcclusion& operator=(const AmbientOcclusion&) = delete;

    // Switches the chain. A mode that cannot run here (a GPU feature missing, a compositor that
    // does not compile) falls back to "off" and returns false; failureReason() says why.
    bool setMode(const std::string& mode);
    const std::string& failureReason() const { return failure_; }
    // Pretend the GPU has at most this many simultaneous render targets (a debug setting that lets
    // tests walk the missing-feature path on a GPU that has them all); 0 = the real number.
    void limitRenderTargets(int n) { renderTargetLimit_ = n; }
    // Renders the level's top-down height map for the heightfield mode: the highest surface over
    // each spot of `bounds` (world space), leaving out objects whose visibility flags are all in
    // `excludeFlags` (the sky). Call once the level is built; until then heightfield = horizon.
    void buildHeightMap(Ogre::SceneManager& scene, const Ogre::AxisAlignedBox& bounds, Ogre::uint32 excludeFlags);
    const std::string& mode() const { return mode_; }
    // Radius, intensity and samples apply at the next frame; the resolution at the next setMode.
    void setKnobs(const AoKnobs& k) { knobs_ = k; }
    void setAoOnly(bool on) { aoOnly_ = on; }
    // The volumes to ray-march this frame (at most 4; more are ignored), with the export's density
    // scale and the game time (the sub-grid noise drifts with it).
    void setVolumes(std::vector<VolumeBinding> volumes, float densityScale, float time);
    bool aoOnly() const { return aoOnly_; }

    // Ogre::CompositorInstance::Listener
    void notifyMaterialSetup(Ogre::uint32 passId, Ogre::MaterialPtr& mat) override;
    void notifyMaterialRender(Ogre::uint32 passId, Ogre::MaterialPtr& mat) override;
    // Ogre::MaterialManager::Listener: the GBuffer scheme for every material.
    Ogre::Technique* handleSchemeNotFound(unsigned short schemeIndex, const Ogre::String& schemeName,
                                          Ogre::Material* originalMaterial, unsigned short lodIndex,
                                          const Ogre::Renderable* rend) override;

private:
    void removeCompositors();
    std::string missingFeatures() const;
    void bindVolumes(Ogre::Pass& pass, Ogre::GpuProgramParameters& fp);

    Ogre::Viewport& viewport_;
    Ogre::Camera& camera_;
    Ogre::TexturePtr noise_;
    Ogre::MaterialPtr gbufferMaterial_, heightMaterial_;
    Ogre::TexturePtr heightMap_;
    Ogre::Matrix4 heightViewProj_ = Ogre::Matrix4::IDENTITY;
    std::vector<float> hemisphereKernel_, sphereKernel_;  // 32 x vec3 each
    std::vector<Ogre::CompositorInstance*> instances_;
    std::string mode_ = "off";
    AoKnobs knobs_;
    bool aoOnly_ = false;
    double resolution_ = 0.25;
    int renderTargetLimit_ = 0;
    std::string failure_;
    std::vector<VolumeBinding> volumes_;
    float volumeDensityScale_ = 1, volumeTime_ = 0;
    Ogre::TexturePtr noVolume_;  // 1x1x1, bound to unused smoke units
    bool plainChain_ = false;    // GBuffer + Plain: AO off, smoke on
    bool smokeBuffer_ = false;   // the smoke pass at half resolution (else 1x1)
};

}  // namespace obscura::ssao
