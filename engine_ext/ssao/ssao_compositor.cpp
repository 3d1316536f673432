// See ssao_compositor.h.
#include "ssao/ssao_compositor.h"

#include "core/rng.h"
#include "ssao/ssao_kernel.h"

#include <Ogre.h>
#include <OgreCompositorManager.h>

namespace obscura::ssao {

namespace {
// Pass identifiers (media/ssao/ssao.compositor).
constexpr Ogre::uint32 kBlurX = 1, kBlurY = 2, kAoPass = 10, kModulate = 20;
constexpr int kMaxSamples = 32;          // the shaders' kernel[] size
constexpr int kNoiseSize = 4;            // 4x4 interleaved rotations: the blur's 5 taps cover it
const char* const kScheme = "GBuffer";

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

    gbufferMaterial_ = Ogre::MaterialManager::getSingleton().getByName("Obscura/SSAO/GBuffer");
    if (!gbufferMaterial_) throw std::runtime_error("material Obscura/SSAO/GBuffer is missing (media/ssao/ssao.material)");
    gbufferMaterial_->load();
    Ogre::MaterialManager::getSingleton().addListener(this, kScheme);
}

AmbientOcclusion::~AmbientOcclusion() {
    removeCompositors();
    Ogre::MaterialManager::getSingleton().removeListener(this, kScheme);
    gbufferMaterial_.reset();
    Ogre::TextureManager::getSingleton().remove(noise_);
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
    if (mode == mode_ && halfResolution_ == knobs_.halfResolution) return true;
    removeCompositors();
    halfResolution_ = knobs_.halfResolution;
    mode_ = "off";
    if (mode == "off") return true;
    auto& cm = Ogre::CompositorManager::getSingleton();
    for (const std::string& name : {std::string("Obscura/SSAO/GBuffer"), compositorFor(mode)}) {
        // The AO buffers' size is the one knob the script leaves to code.
        if (auto comp = cm.getByName(name, Ogre::RGN_DEFAULT))
            for (size_t t = 0; t < comp->getNumTechniques(); ++t)
                for (const char* buffer : {"ao", "blurX", "blurY"})
                    if (auto* def = comp->getTechnique(t)->getTextureDefinition(buffer))
                        def->widthFactor = def->heightFactor = halfResolution_ ? 0.5f : 1.0f;
        Ogre::CompositorInstance* inst = cm.addCompositor(&viewport_, name);
        if (!inst) {
            Ogre::LogManager::getSingleton().logError("AO mode '" + mode + "': compositor " + name +
                                                      " cannot run here (see above); AO off");
            removeCompositors();
            return false;
        }
        inst->addListener(this);
        inst->setEnabled(true);
        instances_.push_back(inst);
    }
    mode_ = mode;
    return true;
}

void AmbientOcclusion::notifyMaterialSetup(Ogre::uint32 passId, Ogre::MaterialPtr& mat) {
    // The noise texture is made here, not found on disk: bind it to the AO passes' noiseMap unit.
    if (passId == kAoPass) mat->getTechnique(0)->getPass(0)->getTextureUnitState("noiseMap")->setTexture(noise_);
}

void AmbientOcclusion::notifyMaterialRender(Ogre::uint32 passId, Ogre::MaterialPtr& mat) {
    Ogre::Pass* pass = mat->getBestTechnique()->getPass(0);
    if (!pass->hasFragmentProgram()) return;
    Ogre::GpuProgramParametersSharedPtr fp = pass->getFragmentProgramParameters();
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
    } else if (passId == kBlurX || passId == kBlurY) {
        const Ogre::TextureUnitState* in = pass->getTextureUnitState(0);
        const auto tex = in->_getTexturePtr();
        const float w = tex ? static_cast<float>(tex->getWidth()) : 1.0f, h = tex ? static_cast<float>(tex->getHeight()) : 1.0f;
        fp->setNamedConstant("direction", passId == kBlurX ? Ogre::Vector2(1.0f / w, 0) : Ogre::Vector2(0, 1.0f / h));
    } else if (passId == kModulate) {
        fp->setNamedConstant("aoOnly", aoOnly_ ? 1.0f : 0.0f);
    }
}

Ogre::Technique* AmbientOcclusion::handleSchemeNotFound(unsigned short, const Ogre::String& schemeName, Ogre::Material*,
                                                        unsigned short, const Ogre::Renderable*) {
    if (schemeName != kScheme) return nullptr;
    // getTechnique, not getBestTechnique: the latter would ask this listener again for GBuffer.
    return gbufferMaterial_->getTechnique(0);
}

}  // namespace obscura::ssao
