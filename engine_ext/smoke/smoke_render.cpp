// See smoke_render.h.
#include "smoke/smoke_render.h"

#include "smoke/smoke_shared.h"

#include <Ogre.h>

#include <OgreHardwarePixelBuffer.h>
#include <OgreTextureManager.h>

#include <algorithm>
#include <string>

namespace obscura::smoke {

namespace {
constexpr Ogre::uint32 kMarchPass = 30;  // media/smoke/smoke.compositor
}

SmokeRender::SmokeRender() {
    Ogre::uint16 emptyCell = 0;
    Ogre::Image emptyVolume;
    emptyVolume.loadDynamicImage(reinterpret_cast<Ogre::uchar*>(&emptyCell), 1, 1, 1, Ogre::PF_RG8);
    noVolume_ = Ogre::TextureManager::getSingleton().loadImage("Obscura/Smoke/NoVolume", Ogre::RGN_DEFAULT, emptyVolume,
                                                              Ogre::TEX_TYPE_3D, 0);
}

SmokeRender::~SmokeRender() {
    for (auto& [id, tex] : textures_) Ogre::TextureManager::getSingleton().remove(tex);
    Ogre::TextureManager::getSingleton().remove(noVolume_);
}

void SmokeRender::update(const SmokeManager& manager, bool stepped, float time) {
    time_ = time;
    densityScale_ = static_cast<float>(manager.settings().exportDensityScale);
    if (!stepped) return;
    auto& tm = Ogre::TextureManager::getSingleton();
    std::map<int, Ogre::TexturePtr> live;
    bindings_.clear();
    for (const auto& entry : manager.volumes()) {
        if (bindings_.size() == SMOKE_MAX_VOLUMES) break;  // the march's samplers; the oldest are marched
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
}

std::string SmokeRender::compositor() const { return bindings_.empty() ? std::string() : "Obscura/Smoke/Volumes"; }

std::string SmokeRender::missingFeature(const frame::Gpu& gpu) const {
    return gpu.renderTargetFormat(Ogre::PF_FLOAT32_RGBA) ? std::string() : "render targets in PF_FLOAT32_RGBA";
}

void SmokeRender::bind(Ogre::uint32 passId, Ogre::Pass& pass, frame::Uniforms& u, const frame::FrameContext& ctx) {
    if (passId != kMarchPass) return;
    const Ogre::Matrix4& proj = ctx.camera->getProjectionMatrix();
    u.set("projScale", Ogre::Vector2(proj[0][0], proj[1][1]));
    u.set("flipY", ctx.flipY ? 1.0f : 0.0f);
    u.set("inverseView", ctx.camera->getViewMatrix().inverse());
    u.set("smokeCount", static_cast<float>(bindings_.size()));
    u.set("smokeDensityScale", densityScale_);
    u.set("smokeTime", time_);
    float mins[SMOKE_MAX_VOLUMES * 3] = {}, sizes[SMOKE_MAX_VOLUMES * 3] = {}, boxMins[SMOKE_MAX_VOLUMES * 3] = {},
          boxSizes[SMOKE_MAX_VOLUMES * 3] = {};
    for (std::size_t i = 0; i < SMOKE_MAX_VOLUMES; ++i) {
        const bool used = i < bindings_.size();
        if (auto* unit = pass.getTextureUnitState("smokeMap" + std::to_string(i))) unit->setTexture(used ? bindings_[i].texture : noVolume_);
        if (!used) continue;
        for (int c = 0; c < 3; ++c) {
            mins[i * 3 + c] = bindings_[i].min[c];
            sizes[i * 3 + c] = bindings_[i].size[c];
            boxMins[i * 3 + c] = bindings_[i].occupiedMin[c];
            boxSizes[i * 3 + c] = bindings_[i].occupiedSize[c];
        }
    }
    u.setArray("smokeMin", mins, SMOKE_MAX_VOLUMES, 3);
    u.setArray("smokeSize", sizes, SMOKE_MAX_VOLUMES, 3);
    u.setArray("smokeBoxMin", boxMins, SMOKE_MAX_VOLUMES, 3);
    u.setArray("smokeBoxSize", boxSizes, SMOKE_MAX_VOLUMES, 3);
}

}  // namespace obscura::smoke
