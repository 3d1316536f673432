// See ssao_compositor.h.
#include "ssao/ssao_compositor.h"

#include "core/rng.h"
#include "ssao/ssao_kernel.h"

#include <Ogre.h>
#include <OgreCompositorManager.h>

namespace obscura::ssao {

namespace {
// Pass identifiers (media/ssao/ssao.compositor).
constexpr Ogre::uint32 kBlurX = 1, kBlurY = 2, kAoPass = 10, kComposite = 20, kPlainComposite = 21, kSmokeMarch = 30;
constexpr std::size_t kMaxVolumes = 4;   // the composite's smoke samplers
constexpr int kMaxSamples = 32;          // the shaders' kernel[] size
constexpr int kNoiseSize = 4;            // 4x4 interleaved rotations: the blur's 5 taps cover it
constexpr int kRenderTargets = 4;        // the G-buffer's (media/ssao/ssao.compositor)
// 1024^2 texels: 10 cm over the arena, 15 cm over e3m4; 4 MB, rendered once per level.
constexpr unsigned kHeightMapSize = 1024;
constexpr float kNoHeight = -1e4f;       // metres: "nothing here" in the height map
const char* const kScheme = "GBuffer";
const char* const kHeightScheme = "AOHeight";

std::vector<float> flatten(const std::vector<Vec3>& v) {
    std::vector<float> f;
    for (const auto& p : v) {
        f.push_back(static_cast<float>(p.x));
        f.push_back(static_cast<float>(p.y));
        f.push_back(static_cast<float>(p.z));
    }
    return f;
}

std::string compositorFor(const std::string& mode) {
    std::string name = mode;
    name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
    return "Obscura/SSAO/" + name;
}
}  // namespace

AmbientOcclusion::AmbientOcclusion(Ogre::Viewport& viewport, Ogre::Camera& camera, std::uint64_t seed)
    : viewport_(viewport), camera_(camera) {
    // Kernels: the relaxed hemisphere for normal-oriented modes, the relaxed sphere for Crytek.
    hemisphereKernel_ = flatten(makeKernel(kMaxSamples, KernelShape::Hemisphere, seed));
    sphereKernel_ = flatten(makeKernel(kMaxSamples, KernelShape::Sphere, seed));

    // Per-pixel random rotations, seeded like everything else.
    Rng rng(seed ^ 0xa0a0u);
    std::vector<Ogre::uint8> pixels;
    for (int i = 0; i < kNoiseSize * kNoiseSize; ++i) {
        Vec3 v{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        v = normalize(v);
        for (double c : {v.x, v.y, v.z}) pixels.push_back(static_cast<Ogre::uint8>((c * 0.5 + 0.5) * 255.0 + 0.5));
        pixels.push_back(255);
    }
    Ogre::Image image;
    image.loadDynamicImage(pixels.data(), kNoiseSize, kNoiseSize, 1, Ogre::PF_BYTE_RGBA);
    noise_ = Ogre::TextureManager::getSingleton().loadImage("Obscura/SSAO/Noise", Ogre::RGN_DEFAULT, image,
                                                           Ogre::TEX_TYPE_2D, 0);

    auto& mm = Ogre::MaterialManager::getSingleton();
    gbufferMaterial_ = mm.getByName("Obscura/Level/GBufferFallback");
    heightMaterial_ = mm.getByName("Obscura/SSAO/HeightMap");
    if (!gbufferMaterial_ || !heightMaterial_)
        throw std::runtime_error("materials Obscura/Level/GBufferFallback (media/materials/level.material) or "
                                 "Obscura/SSAO/HeightMap (media/ssao/ssao.material) are missing");
    gbufferMaterial_->load();
    heightMaterial_->load();
    mm.addListener(this, kScheme);
    mm.addListener(this, kHeightScheme);

    // Unused smoke units get an empty 1x1x1 volume.
    Ogre::uint16 emptyCell = 0;
    Ogre::Image emptyVolume;
    emptyVolume.loadDynamicImage(reinterpret_cast<Ogre::uchar*>(&emptyCell), 1, 1, 1, Ogre::PF_RG8);
    noVolume_ = Ogre::TextureManager::getSingleton().loadImage("Obscura/SSAO/NoVolume", Ogre::RGN_DEFAULT, emptyVolume,
                                                              Ogre::TEX_TYPE_3D, 0);

    // Until buildHeightMap: one texel of "nothing", so heightfield reads as the horizon mode.
    const float none = kNoHeight;
    Ogre::Image flat;
    flat.loadDynamicImage(reinterpret_cast<Ogre::uchar*>(const_cast<float*>(&none)), 1, 1, 1, Ogre::PF_FLOAT32_R);
    heightMap_ = Ogre::TextureManager::getSingleton().loadImage("Obscura/SSAO/NoHeightMap", Ogre::RGN_DEFAULT, flat,
                                                               Ogre::TEX_TYPE_2D, 0);
}

void AmbientOcclusion::buildHeightMap(Ogre::SceneManager& scene, const Ogre::AxisAlignedBox& bounds,
                                      Ogre::uint32 excludeFlags) {
    if (bounds.isNull() || bounds.isInfinite()) return;
    auto& tm = Ogre::TextureManager::getSingleton();
    tm.remove(heightMap_);
    heightMap_ = tm.createManual("Obscura/SSAO/HeightMap", Ogre::RGN_DEFAULT, Ogre::TEX_TYPE_2D, kHeightMapSize,
                                 kHeightMapSize, 0, Ogre::PF_FLOAT32_R, Ogre::TU_RENDERTARGET);
    Ogre::RenderTexture* rt = heightMap_->getBuffer()->getRenderTarget();
    rt->setAutoUpdated(false);

    // An orthographic camera over the level looking straight down; nearest = highest.
    const Ogre::Vector3 c = bounds.getCenter(), size = bounds.getSize();
    Ogre::Camera* cam = scene.createCamera("Obscura/SSAO/HeightCamera");
    Ogre::SceneNode* node = scene.getRootSceneNode()->createChildSceneNode(Ogre::Vector3(c.x, bounds.getMaximum().y + 1, c.z));
    node->setFixedYawAxis(false);
    node->setOrientation(Ogre::Quaternion(Ogre::Degree(-90), Ogre::Vector3::UNIT_X));  // looks down -Y, up = -Z
    node->attachObject(cam);
    cam->setProjectionType(Ogre::PT_ORTHOGRAPHIC);
    cam->setOrthoWindow(size.x, size.z);
    cam->setNearClipDistance(0.5f);
    cam->setFarClipDistance(size.y + 2);

    Ogre::Viewport* vp = rt->addViewport(cam);
    vp->setClearEveryFrame(true);
    vp->setBackgroundColour(Ogre::ColourValue(kNoHeight, kNoHeight, kNoHeight, 1));
    vp->setMaterialScheme(kHeightScheme);
    vp->setShadowsEnabled(false);
    vp->setOverlaysEnabled(false);
    vp->setSkiesEnabled(false);
    vp->setVisibilityMask(~excludeFlags);
    rt->update();
    {   // One log line to check the map by: how much of the level it covers, and the height range.
        std::vector<float> texels(kHeightMapSize * kHeightMapSize);
        heightMap_->getBuffer()->blitToMemory(Ogre::PixelBox(kHeightMapSize, kHeightMapSize, 1, Ogre::PF_FLOAT32_R, texels.data()));
        std::size_t hit = 0;
        float lo = 1e30f, hi = -1e30f;
        for (float h : texels)
            if (h > kNoHeight * 0.5f) {
                ++hit;
                lo = std::min(lo, h);
                hi = std::max(hi, h);
            }
        Ogre::LogManager::getSingleton().stream() << "AO height map: " << kHeightMapSize << "^2 over " << size.x << " x "
                                                  << size.z << " m, " << (100.0 * hit / texels.size())
                                                  << "% covered, heights " << lo << " .. " << hi << " m";
    }

    // world -> texture: the texture is stored upside down when the render system flips RTTs.
    Ogre::Matrix4 flip = Ogre::Matrix4::IDENTITY;
    if (rt->requiresTextureFlipping()) flip[1][1] = -1;
    heightViewProj_ = flip * cam->getProjectionMatrix() * cam->getViewMatrix();

    rt->removeAllViewports();
    node->detachAllObjects();
    scene.destroySceneNode(node);
    scene.destroyCamera(cam);
    if (mode_ == "heightfield") {  // rebind: the material holds the old texture
        const std::string m = mode_;
        mode_ = "off";
        setMode(m);
    }
}

AmbientOcclusion::~AmbientOcclusion() {
    removeCompositors();
    Ogre::MaterialManager::getSingleton().removeListener(this, kScheme);
    Ogre::MaterialManager::getSingleton().removeListener(this, kHeightScheme);
    gbufferMaterial_.reset();
    heightMaterial_.reset();
    Ogre::TextureManager::getSingleton().remove(noise_);
    Ogre::TextureManager::getSingleton().remove(heightMap_);
    Ogre::TextureManager::getSingleton().remove(noVolume_);
}

void AmbientOcclusion::setVolumes(std::vector<VolumeBinding> volumes, float densityScale, float time) {
    if (volumes.size() > kMaxVolumes) volumes.resize(kMaxVolumes);
    volumes_ = std::move(volumes);
    volumeDensityScale_ = densityScale;
    volumeTime_ = time;
    // The smoke pass runs at half resolution only while there is smoke (1x1 otherwise), and with AO
    // off the plain chain exists only then: rebuild the chain when smoke comes or goes.
    if (smokeBuffer_ != !volumes_.empty()) {
        const std::string m = mode_;
        mode_.clear();
        setMode(m);
    }
}

void AmbientOcclusion::removeCompositors() {
    auto& cm = Ogre::CompositorManager::getSingleton();
    for (auto* inst : instances_) {
        inst->removeListener(this);
        cm.removeCompositor(&viewport_, inst->getCompositor()->getName());
    }
    instances_.clear();
}

bool AmbientOcclusion::setMode(const std::string& mode) {
    const bool smoke = !volumes_.empty(), plain = mode == "off" && smoke;
    if (mode == mode_ && resolution_ == knobs_.resolution && plain == plainChain_ && smoke == smokeBuffer_) return true;
    removeCompositors();
    resolution_ = knobs_.resolution;
    mode_ = "off";
    plainChain_ = false;
    smokeBuffer_ = smoke;
    failure_.clear();
    if (mode == "off" && !plain) return true;
    failure_ = missingFeatures();
    if (!failure_.empty()) {
        failure_ = "AO mode '" + mode + "' needs " + failure_ + "; AO off";
        Ogre::LogManager::getSingleton().logError(failure_);
        return false;
    }
    auto& cm = Ogre::CompositorManager::getSingleton();
    for (const std::string& name : {std::string("Obscura/SSAO/GBuffer"), plain ? std::string("Obscura/SSAO/Plain") : compositorFor(mode)}) {
        // The buffers' sizes are the knobs the script leaves to code: the AO's resolution setting,
        // and the smoke's half resolution only while there is smoke (an idle half-resolution pass
        // cost 2-4 ms a frame on llvmpipe).
        if (auto comp = cm.getByName(name, Ogre::RGN_DEFAULT))
            for (size_t t = 0; t < comp->getNumTechniques(); ++t) {
                for (const char* buffer : {"ao", "blurX", "blurY"})
                    if (auto* def = comp->getTechnique(t)->getTextureDefinition(buffer))
                        def->widthFactor = def->heightFactor = static_cast<float>(resolution_);
                if (auto* def = comp->getTechnique(t)->getTextureDefinition("smoke")) {
                    def->width = def->height = smoke ? 0 : 1;
                    def->widthFactor = def->heightFactor = smoke ? 0.5f : 1.0f;
                }
            }
        Ogre::CompositorInstance* inst = cm.addCompositor(&viewport_, name);
        if (!inst || !inst->getTechnique()) {
            failure_ = "AO mode '" + mode + "': compositor " + name + " cannot run here (see the OGRE log); AO off";
            Ogre::LogManager::getSingleton().logError(failure_);
            removeCompositors();
            return false;
        }
        inst->addListener(this);
        inst->setEnabled(true);
        instances_.push_back(inst);
    }
    mode_ = mode;
    plainChain_ = plain;
    return true;
}

void AmbientOcclusion::bindVolumes(Ogre::Pass& pass, Ogre::GpuProgramParameters& fp) {
    const Ogre::Matrix4& proj = camera_.getProjectionMatrix();
    fp.setNamedConstant("projScale", Ogre::Vector2(proj[0][0], proj[1][1]));
    fp.setNamedConstant("flipY", viewport_.getTarget()->requiresTextureFlipping() ? 1.0f : 0.0f);
    fp.setNamedConstant("inverseView", camera_.getViewMatrix().inverse());
    fp.setNamedConstant("smokeCount", static_cast<float>(volumes_.size()));
    fp.setNamedConstant("smokeDensityScale", volumeDensityScale_);
    fp.setNamedConstant("smokeTime", volumeTime_);
    float mins[kMaxVolumes * 3] = {}, sizes[kMaxVolumes * 3] = {}, boxMins[kMaxVolumes * 3] = {}, boxSizes[kMaxVolumes * 3] = {};
    for (std::size_t i = 0; i < kMaxVolumes; ++i) {
        const bool used = i < volumes_.size();
        if (auto* unit = pass.getTextureUnitState("smokeMap" + std::to_string(i)))
            unit->setTexture(used ? volumes_[i].texture : noVolume_);
        if (!used) continue;
        for (int c = 0; c < 3; ++c) {
            mins[i * 3 + c] = volumes_[i].min[c];
            sizes[i * 3 + c] = volumes_[i].size[c];
            boxMins[i * 3 + c] = volumes_[i].occupiedMin[c];
            boxSizes[i * 3 + c] = volumes_[i].occupiedSize[c];
        }
    }
    fp.setNamedConstant("smokeMin", mins, kMaxVolumes, 3);
    fp.setNamedConstant("smokeSize", sizes, kMaxVolumes, 3);
    fp.setNamedConstant("smokeBoxMin", boxMins, kMaxVolumes, 3);
    fp.setNamedConstant("smokeBoxSize", boxSizes, kMaxVolumes, 3);
}

std::string AmbientOcclusion::missingFeatures() const {
    const Ogre::RenderSystemCapabilities* caps = Ogre::Root::getSingleton().getRenderSystem()->getCapabilities();
    int targets = caps ? caps->getNumMultiRenderTargets() : 0;
    if (renderTargetLimit_ > 0) targets = std::min(targets, renderTargetLimit_);
    if (targets < kRenderTargets)
        return std::to_string(kRenderTargets) + " simultaneous render targets and this GPU has " + std::to_string(targets);
    auto& tm = Ogre::TextureManager::getSingleton();
    for (Ogre::PixelFormat f : {Ogre::PF_FLOAT32_R, Ogre::PF_FLOAT32_GR})
        if (!tm.isFormatSupported(Ogre::TEX_TYPE_2D, f, Ogre::TU_RENDERTARGET))
            return "render targets in " + Ogre::PixelUtil::getFormatName(f) + ", which this GPU lacks";
    return {};
}

void AmbientOcclusion::notifyMaterialSetup(Ogre::uint32 passId, Ogre::MaterialPtr& mat) {
    // The noise texture and the height map are made here, not found on disk: bind them by unit name.
    if (passId != kAoPass) return;
    Ogre::Pass* pass = mat->getTechnique(0)->getPass(0);
    pass->getTextureUnitState("noiseMap")->setTexture(noise_);
    if (auto* heights = pass->getTextureUnitState("heightMap")) heights->setTexture(heightMap_);
}

void AmbientOcclusion::notifyMaterialRender(Ogre::uint32 passId, Ogre::MaterialPtr& mat) {
    Ogre::Pass* pass = mat->getBestTechnique()->getPass(0);
    if (!pass->hasFragmentProgram()) return;
    Ogre::GpuProgramParametersSharedPtr fp = pass->getFragmentProgramParameters();
    // A mode's shader need not use every knob (the GLSL compiler drops unused uniforms): never throw
    // inside the frame for that.
    fp->setIgnoreMissingParams(true);
    if (passId == kAoPass) {
        const Ogre::Matrix4& proj = camera_.getProjectionMatrix();
        fp->setNamedConstant("projScale", Ogre::Vector2(proj[0][0], proj[1][1]));
        const bool flip = viewport_.getTarget()->requiresTextureFlipping();
        fp->setNamedConstant("flipY", flip ? 1.0f : 0.0f);
        fp->setNamedConstant("radius", static_cast<float>(knobs_.radius));
        fp->setNamedConstant("intensity", static_cast<float>(knobs_.intensity));
        fp->setNamedConstant("sampleCount", static_cast<float>(std::clamp(knobs_.samples, 1, kMaxSamples)));
        // Sphere kernels for the depth-only and cone modes, hemispheres for the normal-oriented one.
        const auto& k = mode_ == "crytek" || mode_ == "cone" ? sphereKernel_ : hemisphereKernel_;
        fp->setNamedConstant("kernel", k.data(), static_cast<size_t>(kMaxSamples), 3);
        if (mode_ == "heightfield") {
            fp->setNamedConstant("inverseView", camera_.getViewMatrix().inverse());
            fp->setNamedConstant("heightViewProj", heightViewProj_);
        }
    } else if (passId == kBlurX || passId == kBlurY) {
        fp->setNamedConstant("direction", passId == kBlurX ? Ogre::Vector2(1, 0) : Ogre::Vector2(0, 1));
    } else if (passId == kComposite || passId == kPlainComposite) {
        fp->setNamedConstant("aoOnly", aoOnly_ && passId == kComposite ? 1.0f : 0.0f);
        fp->setNamedConstant("aoPresent", passId == kComposite ? 1.0f : 0.0f);
        fp->setNamedConstant("smokePresent", volumes_.empty() ? 0.0f : 1.0f);
    } else if (passId == kSmokeMarch) {
        bindVolumes(*pass, *fp);
    }
}

Ogre::Technique* AmbientOcclusion::handleSchemeNotFound(unsigned short, const Ogre::String& schemeName, Ogre::Material*,
                                                        unsigned short, const Ogre::Renderable*) {
    // getTechnique, not getBestTechnique: the latter would ask this listener again.
    if (schemeName == kScheme) return gbufferMaterial_->getTechnique(0);
    if (schemeName == kHeightScheme) return heightMaterial_->getTechnique(0);
    return nullptr;
}

}  // namespace obscura::ssao
