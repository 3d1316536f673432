// See smoke_render.h.
#include "smoke/smoke_render.h"

#include "smoke/smoke_shared.h"

#include <Ogre.h>

#include <OgreHardwarePixelBuffer.h>
#include <OgreTextureManager.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <string>
#include <tuple>

namespace obscura::smoke {

namespace {
// Density below which a cell does not count towards the marched box (what the RG8 texture
// rounded to 0, so the box is as big as it was): 1 m of it passes 98.4 %
// at the solver's shadowSigma (4 /m), nothing to see.
constexpr float kVisibleDensity = 0.004f;
// The lamp maps' channels (RGBA) and how many of them the signs may take: SIGN_MAX_LIGHTS (2)
// signs are lit at a time (engine_ext/signs), so at least two channels stay for the level's lamps.
constexpr std::size_t kShadowedLamps = 4, kShadowedSignLamps = 2;

// The distance from p to the nearest point of a binding's occupied box.
float distanceToBox(const Ogre::Vector3& p, const Ogre::Vector3& lo, const Ogre::Vector3& size) {
    Ogre::Vector3 nearest = p;
    nearest.makeCeil(lo);
    nearest.makeFloor(lo + size);
    return p.distance(nearest);
}
}  // namespace

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
}

SmokeRender::~SmokeRender() {
    if (uploads_ > 0 && Ogre::LogManager::getSingletonPtr()) {
        std::ostringstream os;
        const double n = static_cast<double>(uploads_);
        os << "smoke: " << uploads_ << " volume uploads, mean " << exportSeconds_ * 1e3 / n << " ms export (exportRGBFloat) + "
           << uploadSeconds_ * 1e3 / n << " ms PF_FLOAT32_RGB blit + " << lampSeconds_ * 1e3 / n
           << " ms lamp maps (exportLampTransmittance + PF_FLOAT32_RGBA blit)";
        Ogre::LogManager::getSingleton().logMessage(os.str());
    }
    for (auto& [id, tex] : textures_) Ogre::TextureManager::getSingleton().remove(tex);
    for (auto& [id, tex] : lampTextures_) Ogre::TextureManager::getSingleton().remove(tex);
    Ogre::TextureManager::getSingleton().remove(noVolume_);
    Ogre::TextureManager::getSingleton().remove(noLampShadow_);
    Ogre::TextureManager::getSingleton().remove(noSunShadow_);
}

void SmokeRender::setLights(Ogre::SceneManager& scene) {
    lights_.clear();
    for (const auto& [name, object] : scene.getMovableObjects(Ogre::LightFactory::FACTORY_TYPE_NAME)) {
        const auto* light = static_cast<const Ogre::Light*>(object);
        if (light->getType() != Ogre::Light::LT_POINT || !light->isVisible()) continue;
        const Ogre::ColourValue c = light->getDiffuseColour() * light->getPowerScale();
        lights_.push_back({light->getDerivedPosition(), Ogre::Vector3(c.r, c.g, c.b), light->getAttenuationRange()});
    }
    // The collection is keyed by name (OGRE's generated names): sort by position so the choice of
    // lights on a tie does not depend on the names.
    std::sort(lights_.begin(), lights_.end(), [](const PointLight& a, const PointLight& b) {
        return std::tie(a.position.x, a.position.y, a.position.z) < std::tie(b.position.x, b.position.y, b.position.z);
    });
}

// The lights whose range reaches any marched box, the brightest at its nearest point of a box
// first, at most SMOKE_MAX_LIGHTS.
void SmokeRender::chooseLights() {
    std::vector<std::pair<float, std::size_t>> scored;
    for (std::size_t l = 0; l < lights_.size(); ++l) {
        const PointLight& p = lights_[l];
        float best = 0.f;
        for (const Binding& b : bindings_) {
            const float d = distanceToBox(p.position, b.occupiedMin, b.occupiedSize);
            if (d >= p.range) continue;
            const float f = 1.f - d / p.range;
            best = std::max(best, (0.2126f * p.colour.x + 0.7152f * p.colour.y + 0.0722f * p.colour.z) * f * f);
        }
        if (best > 0.f) scored.push_back({-best, l});
    }
    std::sort(scored.begin(), scored.end());
    bound_.clear();
    for (std::size_t i = 0; i < scored.size() && i < SMOKE_MAX_LIGHTS; ++i) bound_.push_back(lights_[scored[i].second]);
}

// The lamp maps' channels: the signs' lamps whose range reaches a marched box (the nearest first,
// at most kShadowedSignLamps), and before them the brightest bound level lamps, as many as leave
// room: the level's brightest lamps are shadowed, the rest of bound_ light the smoke unshadowed.
void SmokeRender::chooseShadowedLamps() {
    std::vector<std::pair<float, std::size_t>> signs;
    for (std::size_t s = 0; s < signLamps_.size(); ++s) {
        float nearest = signLamps_[s].range;
        for (const Binding& b : bindings_) nearest = std::min(nearest, distanceToBox(signLamps_[s].position, b.occupiedMin, b.occupiedSize));
        if (nearest < signLamps_[s].range) signs.push_back({nearest, s});
    }
    std::sort(signs.begin(), signs.end());
    signs.resize(std::min(signs.size(), kShadowedSignLamps));
    shadowedLevelLamps_ = std::min(bound_.size(), kShadowedLamps - signs.size());
    shadowed_.clear();
    for (std::size_t l = 0; l < shadowedLevelLamps_; ++l) shadowed_.push_back(bound_[l].position);
    for (const auto& [d, s] : signs) shadowed_.push_back(signLamps_[s].position);
    shadowedPositions_.clear();
    for (const Ogre::Vector3& p : shadowed_) shadowedPositions_.push_back({p.x, p.y, p.z});
}

// Each marched volume's lamp map (its texture kept by volume id, like the fields').
void SmokeRender::uploadLampMaps(const std::vector<std::pair<int, const SmokeVolume*>>& marched) {
    auto& tm = Ogre::TextureManager::getSingleton();
    std::map<int, Ogre::TexturePtr> live;
    for (std::size_t i = 0; i < marched.size() && !shadowed_.empty(); ++i) {
        const auto& [id, volume] = marched[i];
        const GridInfo& g = volume->grid();
        Ogre::TexturePtr tex;
        if (auto it = lampTextures_.find(id); it != lampTextures_.end()) {
            tex = it->second;
            lampTextures_.erase(it);
        } else {
            tex = tm.createManual("Obscura/Smoke/Lamps/" + std::to_string(id), Ogre::RGN_DEFAULT, Ogre::TEX_TYPE_3D,
                                  static_cast<Ogre::uint>(g.nx), static_cast<Ogre::uint>(g.ny), static_cast<Ogre::uint>(g.nz),
                                  0, Ogre::PF_FLOAT32_RGBA, Ogre::TU_DYNAMIC_WRITE_ONLY_DISCARDABLE);
        }
        const auto start = std::chrono::steady_clock::now();
        volume->exportLampTransmittance(shadowedPositions_, buffer_);
        tex->getBuffer()->blitFromMemory(Ogre::PixelBox(static_cast<Ogre::uint32>(g.nx), static_cast<Ogre::uint32>(g.ny),
                                                        static_cast<Ogre::uint32>(g.nz), Ogre::PF_FLOAT32_RGBA, buffer_.data()));
        lampSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        live[id] = tex;
        bindings_[i].lampTexture = tex;
    }
    for (auto& [id, tex] : lampTextures_) tm.remove(tex);  // volumes that finished or are not marched
    lampTextures_ = std::move(live);
}

void SmokeRender::update(const SmokeManager& manager, bool stepped, float time) {
    time_ = time;
    sigma_ = static_cast<float>(manager.settings().shadowSigma);
    if (!stepped) return;
    auto& tm = Ogre::TextureManager::getSingleton();
    std::map<int, Ogre::TexturePtr> live;
    std::vector<std::pair<int, const SmokeVolume*>> marched;  // bindings_'s volumes
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
                                  0, Ogre::PF_FLOAT32_RGB, Ogre::TU_DYNAMIC_WRITE_ONLY_DISCARDABLE);
        }
        const auto start = std::chrono::steady_clock::now();
        entry.volume.exportRGBFloat(buffer_);
        const auto exported = std::chrono::steady_clock::now();
        tex->getBuffer()->blitFromMemory(Ogre::PixelBox(static_cast<Ogre::uint32>(g.nx), static_cast<Ogre::uint32>(g.ny),
                                                        static_cast<Ogre::uint32>(g.nz), Ogre::PF_FLOAT32_RGB, buffer_.data()));
        exportSeconds_ += std::chrono::duration<double>(exported - start).count();
        uploadSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - exported).count();
        ++uploads_;
        live[entry.id] = tex;
        // The cells holding any smoke, one cell wider (trilinear reach): empty space is not marched.
        int lo[3] = {g.nx, g.ny, g.nz}, hi[3] = {-1, -1, -1};
        for (int k = 0; k < g.nz; ++k)
            for (int j = 0; j < g.ny; ++j)
                for (int i = 0; i < g.nx; ++i)
                    if (buffer_[3 * g.index(i, j, k)] > kVisibleDensity) {
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
        bindings_.push_back({tex, noLampShadow_, origin, size, boxMin, boxMax - boxMin});
        marched.push_back({entry.id, &entry.volume});
    }
    for (auto& [id, tex] : textures_) tm.remove(tex);  // volumes that finished
    textures_ = std::move(live);
    chooseLights();
    chooseShadowedLamps();
    uploadLampMaps(marched);
}

std::string SmokeRender::compositor() const { return bindings_.empty() ? std::string() : frame::kVolumesCompositor; }

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
    float lightPos[SMOKE_MAX_LIGHTS * 4] = {}, lightColour[SMOKE_MAX_LIGHTS * 4] = {};
    for (std::size_t i = 0; i < bound_.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            lightPos[i * 4 + c] = bound_[i].position[c];
            lightColour[i * 4 + c] = bound_[i].colour[c];
        }
        lightPos[i * 4 + 3] = std::max(bound_[i].range, 1e-3f);
    }
    u.set("smokeLightCount", static_cast<float>(bound_.size()));
    u.setArray("smokeLightPosition", lightPos, SMOKE_MAX_LIGHTS, 4);
    u.setArray("smokeLightColour", lightColour, SMOKE_MAX_LIGHTS, 4);
    float shadowedPos[kShadowedLamps * 3] = {};
    for (std::size_t i = 0; i < shadowed_.size(); ++i)
        for (int c = 0; c < 3; ++c) shadowedPos[i * 3 + c] = shadowed_[i][c];
    u.set("smokeShadowedCount", static_cast<float>(shadowed_.size()));
    u.set("smokeShadowedLamps", static_cast<float>(shadowedLevelLamps_));
    u.setArray("smokeShadowedPosition", shadowedPos, kShadowedLamps, 3);
}

}  // namespace obscura::smoke
