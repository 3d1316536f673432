// See smoke_textures.h.
#include "smoke/smoke_textures.h"

#include <OgreHardwarePixelBuffer.h>
#include <OgreTextureManager.h>

#include <string>

namespace obscura::smoke {

SmokeTextures::~SmokeTextures() {
    for (auto& [id, tex] : textures_) Ogre::TextureManager::getSingleton().remove(tex);
}

std::vector<ssao::VolumeBinding> SmokeTextures::upload(const SmokeManager& manager) {
    auto& tm = Ogre::TextureManager::getSingleton();
    std::map<int, Ogre::TexturePtr> live;
    bindings_.clear();
    for (const auto& entry : manager.volumes()) {
        const GridInfo& g = entry.volume.grid();
        Ogre::TexturePtr tex;
        if (auto it = textures_.find(entry.id); it != textures_.end()) {
            tex = it->second;
            textures_.erase(it);
        } else {
            tex = tm.createManual("Obscura/Smoke/" + std::to_string(entry.id), Ogre::RGN_DEFAULT, Ogre::TEX_TYPE_3D,
                                  static_cast<Ogre::uint>(g.nx), static_cast<Ogre::uint>(g.ny), static_cast<Ogre::uint>(g.nz),
                                  0, Ogre::PF_RG8, Ogre::TU_DYNAMIC_WRITE_ONLY_DISCARDABLE);
        }
        entry.volume.exportRG8(buffer_);
        tex->getBuffer()->blitFromMemory(Ogre::PixelBox(static_cast<Ogre::uint32>(g.nx), static_cast<Ogre::uint32>(g.ny),
                                                        static_cast<Ogre::uint32>(g.nz), Ogre::PF_RG8, buffer_.data()));
        live[entry.id] = tex;
        const Vec3 size = g.size();
        bindings_.push_back({tex, Ogre::Vector3(static_cast<float>(g.origin.x), static_cast<float>(g.origin.y), static_cast<float>(g.origin.z)),
                             Ogre::Vector3(static_cast<float>(size.x), static_cast<float>(size.y), static_cast<float>(size.z))});
    }
    for (auto& [id, tex] : textures_) tm.remove(tex);  // volumes that finished
    textures_ = std::move(live);
    return bindings_;
}

}  // namespace obscura::smoke
