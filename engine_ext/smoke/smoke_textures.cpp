// See smoke_textures.h.
#include "smoke/smoke_textures.h"

#include <OgreHardwarePixelBuffer.h>
#include <OgreTextureManager.h>

#include <algorithm>
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
        // The cells holding any smoke, one cell wider (trilinear reach): empty space is not marched.
        int lo[3] = {g.nx, g.ny, g.nz}, hi[3] = {-1, -1, -1};
        for (int k = 0; k < g.nz; ++k)
            for (int j = 0; j < g.ny; ++j)
                for (int i = 0; i < g.nx; ++i)
                    if (buffer_[2 * g.index(i, j, k)] != 0) {
                        const int c[3] = {i, j, k};
                        for (int a = 0; a < 3; ++a) {
                            lo[a] = std::min(lo[a], c[a]);
                            hi[a] = std::max(hi[a], c[a]);
                        }
                    }
        if (hi[0] < 0) continue;  // nothing visible yet (or any more)
        const auto f = [](double v) { return static_cast<float>(v); };
        const Ogre::Vector3 origin(f(g.origin.x), f(g.origin.y), f(g.origin.z)), size(f(g.size().x), f(g.size().y), f(g.size().z));
        const float h = f(g.cellSize);
        const Ogre::Vector3 boxMin = origin + Ogre::Vector3(f(lo[0] - 1), f(lo[1] - 1), f(lo[2] - 1)) * h;
        const Ogre::Vector3 boxMax = origin + Ogre::Vector3(f(hi[0] + 2), f(hi[1] + 2), f(hi[2] + 2)) * h;
        bindings_.push_back({tex, origin, size, boxMin, boxMax - boxMin});
    }
    for (auto& [id, tex] : textures_) tm.remove(tex);  // volumes that finished
    textures_ = std::move(live);
    return bindings_;
}

}  // namespace obscura::smoke
