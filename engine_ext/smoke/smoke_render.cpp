// See smoke_render.h.
#include "smoke/smoke_render.h"

#include "render/ogre_convert.h"
#include "smoke/smoke_lamp_light.h"
#include "smoke/smoke_shared.h"

#include <Ogre.h>

#include <OgreHardwarePixelBuffer.h>
#include <OgreTextureManager.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <string>

namespace obscura::smoke {

using render::toOgre;

SmokeRender::SmokeRender() {
    float emptyCell[3] = {0.f, 1.f, 1.f};
    Ogre::Image emptyVolume;
    emptyVolume.loadDynamicImage(reinterpret_cast<Ogre::uchar*>(emptyCell), 1, 1, 1, Ogre::PF_FLOAT32_RGB);
    noVolume_ = Ogre::TextureManager::getSingleton().loadImage("Obscura/Smoke/NoVolume", Ogre::RGN_DEFAULT, emptyVolume,
                                                              Ogre::TEX_TYPE_3D, 0);
    // What the sun's shadow map is cleared to (shadow_caster.frag): no caster, lit everywhere.
    float clear = 1.f;
    Ogre::Image lit;
    lit.loadDynamicImage(reinterpret_cast<Ogre::uchar*>(&clear), 1, 1, 1, Ogre::PF_FLOAT32_R);
    noSunShadow_ = Ogre::TextureManager::getSingleton().loadImage("Obscura/Smoke/NoSunShadow", Ogre::RGN_DEFAULT, lit,
                                                                 Ogre::TEX_TYPE_2D, 0);
    float open[4] = {1.f, 1.f, 1.f, 1.f};
    Ogre::Image unshadowed;
    unshadowed.loadDynamicImage(reinterpret_cast<Ogre::uchar*>(open), 1, 1, 1, Ogre::PF_FLOAT32_RGBA);
    noLampShadow_ = Ogre::TextureManager::getSingleton().loadImage("Obscura/Smoke/NoLampShadow", Ogre::RGN_DEFAULT,
                                                                  unshadowed, Ogre::TEX_TYPE_3D, 0);
    float dark[4] = {0.f, 0.f, 0.f, 0.f};
    Ogre::Image unlit;
    unlit.loadDynamicImage(reinterpret_cast<Ogre::uchar*>(dark), 1, 1, 1, Ogre::PF_FLOAT32_RGBA);
    noLampLight_ = Ogre::TextureManager::getSingleton().loadImage("Obscura/Smoke/NoLampLight", Ogre::RGN_DEFAULT, unlit,
                                                                 Ogre::TEX_TYPE_3D, 0);
}

SmokeRender::~SmokeRender() {
    if (uploads_ > 0 && Ogre::LogManager::getSingletonPtr()) {
        std::ostringstream os;
        const double n = static_cast<double>(uploads_);
        os << "smoke: " << uploads_ << " volume uploads, mean " << exportMs_ / n << " ms export (exportRGBFloat) + "
           << lampMs_ / n  << " ms lamp maps and light (exportLampTransmittance, lampLight) on the worker, "
           << uploadSeconds_ * 1e3 / n << " ms blits (PF_FLOAT32_RGB, PF_FLOAT32_RGBA) on the render thread";
        // What the worker took a step (releases, solver, sun and sky, export, lamp maps): the render
        // thread's burst before the pipeline.
        std::vector<double> w = workerMs_;
        std::sort(w.begin(), w.end());
        const auto rank = [&w](double q) { return w[std::min(w.size() - 1, static_cast<std::size_t>(q * static_cast<double>(w.size())))]; };
        if (!w.empty())
            os << "; the worker's step: median " << rank(0.5) << " ms, p99 " << rank(0.99) << " ms, max " << w.back()
               << " ms over " << w.size() << " steps";
        Ogre::LogManager::getSingleton().logMessage(os.str());
    }
    for (auto& [id, tex] : textures_) Ogre::TextureManager::getSingleton().remove(tex);
    for (auto& [id, tex] : lampTextures_) Ogre::TextureManager::getSingleton().remove(tex);
    if (lampLight_) Ogre::TextureManager::getSingleton().remove(lampLight_);
    Ogre::TextureManager::getSingleton().remove(noLampLight_);
    Ogre::TextureManager::getSingleton().remove(noVolume_);
    Ogre::TextureManager::getSingleton().remove(noLampShadow_);
    Ogre::TextureManager::getSingleton().remove(noSunShadow_);
}

// The texture of volume `id` in `cache` (taken out of it), or a new one; kept in `live`.
Ogre::TexturePtr SmokeRender::textureFor(std::map<int, Ogre::TexturePtr>& cache, std::map<int, Ogre::TexturePtr>& live,
                                         int id, const GridInfo& g, Ogre::PixelFormat format, const std::string& prefix) {
    Ogre::TexturePtr tex;
    if (auto it = cache.find(id); it != cache.end()) {
        tex = it->second;
        cache.erase(it);
    } else {
        tex = Ogre::TextureManager::getSingleton().createManual(
            prefix + std::to_string(id), Ogre::RGN_DEFAULT, Ogre::TEX_TYPE_3D, static_cast<Ogre::uint>(g.nx),
            static_cast<Ogre::uint>(g.ny), static_cast<Ogre::uint>(g.nz), 0, format, Ogre::TU_DYNAMIC_WRITE_ONLY_DISCARDABLE);
    }
    live[id] = tex;
    return tex;
}

void SmokeRender::update(const SmokeFrame& frame, float time, float sigma) {
    const auto start = std::chrono::steady_clock::now();
    time_ = time;
    sigma_ = sigma;
    lastUpdateMs_ = 0;
    if (frame.version == uploadedVersion_) return;
    uploadedVersion_ = frame.version;
    auto& tm = Ogre::TextureManager::getSingleton();
    std::map<int, Ogre::TexturePtr> live, liveLamps;
    bindings_.clear();
    for (const SmokeFrameVolume& v : frame.volumes) {
        const GridInfo& g = v.grid;
        const auto box = [&g](Ogre::PixelFormat format, const float* data) {
            return Ogre::PixelBox(static_cast<Ogre::uint32>(g.nx), static_cast<Ogre::uint32>(g.ny),
                                  static_cast<Ogre::uint32>(g.nz), format, const_cast<float*>(data));
        };
        Ogre::TexturePtr tex = textureFor(textures_, live, v.id, g, Ogre::PF_FLOAT32_RGB, "Obscura/Smoke/");
        tex->getBuffer()->blitFromMemory(box(Ogre::PF_FLOAT32_RGB, v.fields.data()));
        Ogre::TexturePtr lamps = noLampShadow_;
        if (!v.lamps.empty()) {
            lamps = textureFor(lampTextures_, liveLamps, v.id, g, Ogre::PF_FLOAT32_RGBA, "Obscura/Smoke/Lamps/");
            lamps->getBuffer()->blitFromMemory(box(Ogre::PF_FLOAT32_RGBA, v.lamps.data()));
        }
        if (!frame.lamps.bound.empty()) uploadLampLight(bindings_.size(), g, v.light);
        ++uploads_;
        bindings_.push_back({tex, lamps, toOgre(g.origin), toOgre(g.size()), toOgre(v.occupied.min), toOgre(v.occupied.size)});
    }
    for (auto& [id, tex] : textures_) tm.remove(tex);  // volumes that finished or are not marched
    for (auto& [id, tex] : lampTextures_) tm.remove(tex);
    textures_ = std::move(live);
    lampTextures_ = std::move(liveLamps);
    lamps_ = frame.lamps;
    exportMs_ += frame.exportMs;
    lampMs_ += frame.lampMs;
    workerMs_.push_back(frame.commandMs + frame.stepMs + frame.lightMs + frame.exportMs + frame.lampMs);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    uploadSeconds_ += seconds;
    lastUpdateMs_ = seconds * 1e3;
}

// Volume `slot`'s two texel blocks (A, B: smoke_lamp_light.h) into their slabs of the one atlas
// all volumes share (one sampler however many volumes: the pass's 16 texture units are nearly all
// taken), made again when the grid's resolution changes. Every grid is a cube of the same cells.
void SmokeRender::uploadLampLight(std::size_t slot, const GridInfo& g, const std::vector<float>& light) {
    const auto n = static_cast<Ogre::uint32>(g.nx);
    if (!lampLight_ || lampLight_->getWidth() != n) {
        if (lampLight_) Ogre::TextureManager::getSingleton().remove(lampLight_);
        lampLight_ = Ogre::TextureManager::getSingleton().createManual(
            "Obscura/Smoke/LampLight", Ogre::RGN_DEFAULT, Ogre::TEX_TYPE_3D, n, n,
            n * static_cast<Ogre::uint32>(kLampLightTexels * SMOKE_MAX_VOLUMES), 0, Ogre::PF_FLOAT32_RGBA, Ogre::TU_DYNAMIC_WRITE_ONLY);
    }
    const std::size_t block = 4 * g.cells();
    for (std::size_t t = 0; t < kLampLightTexels; ++t) {
        const auto z0 = static_cast<Ogre::uint32>((slot * kLampLightTexels + t) * n);
        Ogre::PixelBox src(n, n, n, Ogre::PF_FLOAT32_RGBA, const_cast<float*>(light.data() + t * block));
        lampLight_->getBuffer()->blitFromMemory(src, Ogre::Box(0, 0, z0, n, n, z0 + n));
    }
}

void SmokeRender::cull(const Ogre::Camera& view, bool shadowing) {
    inView_ = shadowing || std::any_of(bindings_.begin(), bindings_.end(), [&view](const Binding& b) {
                  return view.isVisible(Ogre::AxisAlignedBox(b.occupiedMin, b.occupiedMin + b.occupiedSize));
              });
}

std::string SmokeRender::compositor() const {
    return bindings_.empty() || !inView_ ? std::string() : frame::kVolumesCompositor;
}

std::string SmokeRender::missingFeature(const frame::Gpu& gpu) const {
    return gpu.renderTargetFormat(Ogre::PF_FLOAT32_RGBA) ? std::string() : "render targets in PF_FLOAT32_RGBA";
}

// The sun's shadow map as the level's surfaces see it (texture_viewproj_matrix 0 in
// media/materials/level.material, which a quad pass does not get reliably): OGRE's shadow texture 0
// and world -> map = clip -> texture bias x its camera's projection (render-system depth) x view,
// as AutoParamDataSource::getTextureViewProjMatrix computes it (no camera-relative rendering
// here). Without texture shadows (a level without a sun) or before OGRE made the texture: the 1x1
// "nothing here" map, lit everywhere.
void SmokeRender::bindSunShadow(Ogre::Pass& pass, frame::Uniforms& u, const Ogre::Camera* camera) const {
    Ogre::TexturePtr map = noSunShadow_;
    Ogre::Matrix4 viewProj = Ogre::Matrix4::IDENTITY;
    Ogre::SceneManager* scene = camera ? camera->getSceneManager() : nullptr;
    if (scene && scene->isShadowTechniqueTextureBased() && !scene->getShadowTextureConfigList().empty()) {
        const Ogre::TexturePtr& tex = scene->getShadowTexture(0);
        Ogre::RenderTarget* target = tex ? tex->getBuffer()->getRenderTarget() : nullptr;
        if (target && target->getNumViewports() > 0 && target->getViewport(0)->getCamera()) {
            const Ogre::Camera* cam = target->getViewport(0)->getCamera();
            map = tex;
            viewProj = Ogre::Matrix4::CLIPSPACE2DTOIMAGESPACE * cam->getProjectionMatrixWithRSDepth() * cam->getViewMatrix();
        }
    }
    if (auto* unit = pass.getTextureUnitState("sunShadowMap")) unit->setTexture(map);
    const float w = static_cast<float>(map->getWidth()), h = static_cast<float>(map->getHeight());
    u.set("sunShadowTexel", Ogre::Vector4(1.f / w, 1.f / h, w, h));
    u.set("sunShadowViewProj", viewProj);
}

void SmokeRender::bind(Ogre::uint32 passId, Ogre::Pass& pass, frame::Uniforms& u, const frame::FrameContext& ctx) {
    if (passId != frame::kVolumesPass) return;
    bindSunShadow(pass, u, ctx.camera);
    u.set("smokeCount", static_cast<float>(bindings_.size()));
    u.set("smokeSigma", sigma_);
    u.set("smokeTime", time_);
    float mins[SMOKE_MAX_VOLUMES * 3] = {}, sizes[SMOKE_MAX_VOLUMES * 3] = {}, boxMins[SMOKE_MAX_VOLUMES * 3] = {},
          boxSizes[SMOKE_MAX_VOLUMES * 3] = {};
    for (std::size_t i = 0; i < SMOKE_MAX_VOLUMES; ++i) {
        const bool used = i < bindings_.size();
        if (auto* unit = pass.getTextureUnitState("smokeMap" + std::to_string(i))) unit->setTexture(used ? bindings_[i].texture : noVolume_);
        if (auto* unit = pass.getTextureUnitState("smokeLampMap" + std::to_string(i)))
            unit->setTexture(used ? bindings_[i].lampTexture : noLampShadow_);
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
    // The lamps' light was computed on the grid (the worker's lampLight): the march reads the atlas.
    u.set("smokeLightCount", static_cast<float>(lamps_.bound.size()));
    u.set("smokeLampLightCells", lampLight_ ? static_cast<float>(lampLight_->getWidth()) : 1.f);
    if (auto* unit = pass.getTextureUnitState("smokeLampLight"))
        unit->setTexture(lampLight_ && !lamps_.bound.empty() ? lampLight_ : noLampLight_);
    float shadowedPos[kShadowedLamps * 3] = {};
    for (std::size_t i = 0; i < lamps_.shadowed.size() && i < kShadowedLamps; ++i) {
        const Ogre::Vector3 p = toOgre(lamps_.shadowed[i]);
        for (int k = 0; k < 3; ++k) shadowedPos[i * 3 + k] = p[k];
    }
    u.set("smokeShadowedCount", static_cast<float>(lamps_.shadowed.size()));
    u.setArray("smokeShadowedPosition", shadowedPos, kShadowedLamps, 3);
}

}  // namespace obscura::smoke
