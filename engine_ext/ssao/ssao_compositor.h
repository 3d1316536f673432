// OGRE glue of the AO modes: installs the GBuffer material scheme (every material gets the
// G-buffer technique without edits), the per-pixel noise texture and the kernel, and switches the
// compositor chain on a viewport when the mode changes. Knob values come from the game.
#pragma once

#include <OgreCompositorInstance.h>
#include <OgreMaterialManager.h>
#include <OgreTexture.h>

#include <cstdint>
#include <string>
#include <vector>

namespace Ogre {
class Camera;
class Viewport;
}  // namespace Ogre

namespace obscura::ssao {

struct AoKnobs {
    double radius = 0.6;      // metres: about a hand's span, where contact shadows read
    double intensity = 2.0;   // see game/settings.h
    int samples = 16;         // 16: the seeds' 10-16, at half resolution
    bool halfResolution = true;  // AO computed at half width and height, then blurred up
};

class AmbientOcclusion : public Ogre::CompositorInstance::Listener, public Ogre::MaterialManager::Listener {
public:
    AmbientOcclusion(Ogre::Viewport& viewport, Ogre::Camera& camera, std::uint64_t seed);
    ~AmbientOcclusion() override;
    AmbientOcclusion(const AmbientOcclusion&) = delete;
    AmbientOcclusion& operator=(const AmbientOcclusion&) = delete;

    // Switches the chain; a mode whose compositor cannot run here falls back to "off" and
    // returns false (the reason is in the log).
    bool setMode(const std::string& mode);
    const std::string& mode() const { return mode_; }
    // Radius, intensity and samples apply at the next frame; the resolution at the next setMode.
    void setKnobs(const AoKnobs& k) { knobs_ = k; }
    void setAoOnly(bool on) { aoOnly_ = on; }
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

    Ogre::Viewport& viewport_;
    Ogre::Camera& camera_;
    Ogre::TexturePtr noise_;
    Ogre::MaterialPtr gbufferMaterial_;
    std::vector<float> hemisphereKernel_, sphereKernel_;  // 32 x vec3 each
    std::vector<Ogre::CompositorInstance*> instances_;
    std::string mode_ = "off";
    AoKnobs knobs_;
    bool aoOnly_ = false;
    bool halfResolution_ = true;
};

}  // namespace obscura::ssao
