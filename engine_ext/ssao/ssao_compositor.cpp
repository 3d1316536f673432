// See ssao_compositor.h.
#include "ssao/ssao_compositor.h"

#include "core/rng.h"
#include "ssao/ssao_kernel.h"
#include "ssao/ssao_knobs.h"
#include "ssao/ssao_modes.h"
#include "ssao/ssao_shared.h"

#include <Ogre.h>
#include <OgreCompositionTechnique.h>

namespace obscura::ssao {

namespace {
// Pass identifiers (media/ssao/ssao.compositor).
constexpr Ogre::uint32 kBlurX = 1, kBlurY = 2, kAoPass = 10;
// 1024^2 texels: 10 cm over the arena, 15 cm over e3m4; 4 MB, rendered once per level.
constexpr unsigned kHeightMapSize = 1024;
constexpr float kNoHeight = -1e4f;       // metres: "nothing here" in the height map
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

}  // namespace

AmbientOcclusion::AmbientOcclusion(std::uint64_t seed) {
    // Kernels for every sample count the knob allows, each relaxed for its count (kernelFor): the
    // hemisphere for normal-oriented modes, the sphere for Crytek and cone. ~20 ms at start-up.
    for (int n = 1; n <= SSAO_MAX_SAMPLES; ++n) {
        hemisphereKernels_.push_back(flatten(kernelFor(n, SSAO_MAX_SAMPLES, KernelShape::Hemisphere, seed)));
        sphereKernels_.push_back(flatten(kernelFor(n, SSAO_MAX_SAMPLES, KernelShape::Sphere, seed)));
    }

    // Per-pixel random rotations, seeded like everything else.
    Rng rng(seed ^ 0xa0a0u);
    std::vector<Ogre::uint8> pixels;
    for (int i = 0; i < SSAO_NOISE_SIZE * SSAO_NOISE_SIZE; ++i) {
        Vec3 v{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        v = normalize(v);
        for (double c : {v.x, v.y, v.z}) pixels.push_back(static_cast<Ogre::uint8>((c * 0.5 + 0.5) * 255.0 + 0.5));
        pixels.push_back(255);
    }
    Ogre::Image image;
    image.loadDynamicImage(pixels.data(), SSAO_NOISE_SIZE, SSAO_NOISE_SIZE, 1, Ogre::PF_BYTE_RGBA);
    noise_ = Ogre::TextureManager::getSingleton().loadImage("Obscura/SSAO/Noise", Ogre::RGN_DEFAULT, image,
                                                           Ogre::TEX_TYPE_2D, 0);

    auto& mm = Ogre::MaterialManager::getSingleton();
    heightMaterial_ = mm.getByName("Obscura/SSAO/HeightMap");
    if (!heightMaterial_) throw std::runtime_error("material Obscura/SSAO/HeightMap (media/ssao/ssao.material) is missing");
    heightMaterial_->load();
    mm.addListener(this, kHeightScheme);

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
    ++heightMapVersion_;  // the frame rebuilds the chain: the heightfield pass binds the new map
}

AmbientOcclusion::~AmbientOcclusion() {
    Ogre::MaterialManager::getSingleton().removeListener(this, kHeightScheme);
    heightMaterial_.reset();
    Ogre::TextureManager::getSingleton().remove(noise_);
    Ogre::TextureManager::getSingleton().remove(heightMap_);
}

std::string AmbientOcclusion::compositor() const {
    if (mode_ == "off") return {};
    std::string name = mode_;
    name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
    return "Obscura/SSAO/" + name;
}

std::string AmbientOcclusion::configuration() const {
    return std::to_string(knobs_.resolution) + (readsHeightMap(mode_) ? " map " + std::to_string(heightMapVersion_) : "");
}

std::string AmbientOcclusion::missingFeature(const frame::Gpu& gpu) const {
    return gpu.renderTargetFormat(Ogre::PF_FLOAT32_GR) ? std::string() : "render targets in PF_FLOAT32_GR";
}

void AmbientOcclusion::configure(Ogre::CompositionTechnique& t) const {
    // The buffers' size is the knob the script leaves to code: the AO's resolution setting.
    for (const char* buffer : {"ao", "blurX", "blurY"})
        if (auto* def = t.getTextureDefinition(buffer)) def->widthFactor = def->heightFactor = static_cast<float>(knobs_.resolution);
}

void AmbientOcclusion::setup(Ogre::uint32 passId, Ogre::Pass& pass) {
    // The noise texture and the height map are made here, not found on disk: bind them by unit name.
    if (passId != kAoPass) return;
    pass.getTextureUnitState("noiseMap")->setTexture(noise_);
    if (auto* heights = pass.getTextureUnitState("heightMap")) heights->setTexture(heightMap_);
}

void AmbientOcclusion::bind(Ogre::uint32 passId, Ogre::Pass&, frame::Uniforms& u, const frame::FrameContext& ctx) {
    if (passId == kAoPass) {
        const Ogre::Matrix4& proj = ctx.camera->getProjectionMatrix();
        u.set("projScale", Ogre::Vector2(proj[0][0], proj[1][1]));
        u.set("flipY", ctx.flipY ? 1.0f : 0.0f);
        u.set("radius", static_cast<float>(kRadius.clamp(knobs_.radius)));
        u.set("intensity", static_cast<float>(kIntensity.clamp(knobs_.intensity)));
        const int samples = static_cast<int>(kSamples.clamp(knobs_.samples));
        u.set("sampleCount", static_cast<float>(samples));
        // Sphere kernels for the depth-only and cone modes, hemispheres for the normal-oriented ones.
        const auto& kernels = mode_ == "crytek" || mode_ == "cone" ? sphereKernels_ : hemisphereKernels_;
        u.setArray("kernel", kernels[static_cast<std::size_t>(samples - 1)].data(), SSAO_MAX_SAMPLES, 3);
        // GTAO's visibility is already the cosine-weighted integral: the default intensity leaves it
        // as it is, others raise it to a power (intensity 4 squares it, 1 takes its square root).
        if (mode_ == "gtao" || mode_ == "combined") u.set("visibilityPower", static_cast<float>(kIntensity.clamp(knobs_.intensity) / kIntensity.value));
        if (readsHeightMap(mode_)) {
            u.set("inverseView", ctx.camera->getViewMatrix().inverse());
            u.set("heightViewProj", heightViewProj_);
        }
        if (mode_ == "combined") u.set("largeRadius", static_cast<float>(kLargeRadius.clamp(knobs_.largeRadius)));
    } else if (passId == kBlurX || passId == kBlurY) {
        u.set("direction", passId == kBlurX ? Ogre::Vector2(1, 0) : Ogre::Vector2(0, 1));
    }
}

Ogre::Technique* AmbientOcclusion::handleSchemeNotFound(unsigned short, const Ogre::String& schemeName, Ogre::Material*,
                                                        unsigned short, const Ogre::Renderable*) {
    // getTechnique, not getBestTechnique: the latter would ask this listener again.
    return schemeName == kHeightScheme ? heightMaterial_->getTechnique(0) : nullptr;
}

}  // namespace obscura::ssao
