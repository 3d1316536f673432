// OGRE glue of the smoke grenades: each live volume's packed fields (density, transmittance towards
// the sun; SmokeVolume::exportRG8) uploaded to its own PF_RG8 3D texture after the simulation steps,
// handed to the post-process composite (ssao::AmbientOcclusion::setVolumes) that ray-marches them.
// Textures follow the volumes' ids: made when one appears, dropped when it finishes.
#pragma once

#include "smoke/smoke_manager.h"
#include "ssao/ssao_compositor.h"

#include <OgreTexture.h>

#include <cstdint>
#include <map>
#include <vector>

namespace obscura::smoke {

class SmokeTextures {
public:
    SmokeTextures() = default;
    ~SmokeTextures();
    SmokeTextures(const SmokeTextures&) = delete;
    SmokeTextures& operator=(const SmokeTextures&) = delete;

    // Uploads every volume of `manager` (call after it stepped and computed its transmittance) and
    // returns what the composite should march, oldest volume first.
    std::vector<ssao::VolumeBinding> upload(const SmokeManager& manager);
    // The bindings of the last upload (unchanged textures), for frames between smoke steps.
    const std::vector<ssao::VolumeBinding>& bindings() const { return bindings_; }

private:
    std::map<int, Ogre::TexturePtr> textures_;
    std::vector<ssao::VolumeBinding> bindings_;
    std::vector<std::uint8_t> buffer_;
};

}  // namespace obscura::smoke
