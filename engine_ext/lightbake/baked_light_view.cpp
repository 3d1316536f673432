// See baked_light_view.h.
#include "lightbake/baked_light_view.h"

#include "core/half_float.h"
#include "lightbake/lightbake_shared.h"

#include <OgreGpuProgramManager.h>
#include <OgreHardwarePixelBuffer.h>
#include <OgreMaterialManager.h>
#include <OgrePass.h>
#include <OgreTechnique.h>
#include <OgreTextureManager.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace obscura::lightbake {

namespace {
int serial = 0;  // a texture name of its own per level loaded

// `channels` floats a texel -> RGBA half floats (alpha 1 where the source has none).
std::vector<std::uint16_t> halves(const std::vector<float>& values, int channels, std::size_t texels) {
    std::vector<std::uint16_t> out(texels * 4, toHalf(1.0f));
    for (std::size_t t = 0; t < texels; ++t)
        for (int c = 0; c < channels; ++c) out[t * 4 + c] = toHalf(values[t * channels + c]);
    return out;
}

Ogre::TexturePtr upload(const std::string& name, Ogre::TextureType type, int w, int h, int d, std::vector<std::uint16_t> texels) {
    Ogre::TexturePtr tex = Ogre::TextureManager::getSingleton().createManual(
        name + std::to_string(serial), Ogre::RGN_DEFAULT, type, static_cast<Ogre::uint>(w), static_cast<Ogre::uint>(h),
        static_cast<Ogre::uint>(d), 0, Ogre::PF_FLOAT16_RGBA, Ogre::TU_STATIC_WRITE_ONLY);
    tex->getBuffer()->blitFromMemory(Ogre::PixelBox(static_cast<Ogre::uint32>(w), static_cast<Ogre::uint32>(h),
                                                    static_cast<Ogre::uint32>(d), Ogre::PF_FLOAT16_RGBA, texels.data()));
    return tex;
}

Ogre::GpuSharedParametersPtr sharedParams() {
    auto& gpm = Ogre::GpuProgramManager::getSingleton();
    const auto& all = gpm.getAvailableSharedParameters();
    if (all.find("ObscuraBakedLight") == all.end())
        throw std::runtime_error("shared_params ObscuraBakedLight is missing (media/materials/level.program)");
    return gpm.getSharedParameters("ObscuraBakedLight");
}
}  // namespace

BakedLightView::BakedLightView(const LightBake& bake) {
    ++serial;
    const Atlas& a = bake.atlas;
    direct_ = upload("Obscura/Lightbake/Direct/", Ogre::TEX_TYPE_2D, a.width, a.height, 1, halves(bake.direct, 4, a.texels()));
    indirect_ = upload("Obscura/Lightbake/Indirect/", Ogre::TEX_TYPE_2D, a.width, a.height, 1, halves(bake.indirect, 3, a.texels()));
    const ProbeGrid& g = bake.probes;
    std::vector<float> layers(g.up);
    layers.insert(layers.end(), g.down.begin(), g.down.end());  // z: the up layer's slices, then the down layer's
    const bool probes = g.count() > 0;
    probes_ = upload("Obscura/Lightbake/Probes/", Ogre::TEX_TYPE_3D, probes ? g.nx : 1, probes ? g.ny : 1,
                     probes ? LIGHTBAKE_PROBE_LAYERS * g.nz : LIGHTBAKE_PROBE_LAYERS,
                     probes ? halves(layers, 3, layers.size() / 3) : std::vector<std::uint16_t>(8 * LIGHTBAKE_PROBE_LAYERS, 0));
    auto it = Ogre::MaterialManager::getSingleton().getResourceIterator();
    while (it.hasMoreElements()) bind(*static_cast<Ogre::Material*>(it.getNext().get()));
    Ogre::GpuSharedParametersPtr p = sharedParams();
    p->setNamedConstant("lightProbeOrigin", Ogre::Vector4(static_cast<float>(g.origin.x), static_cast<float>(g.origin.y),
                                                          static_cast<float>(g.origin.z), static_cast<float>(g.cell)));
    p->setNamedConstant("lightProbeSize", Ogre::Vector4(static_cast<float>(std::max(g.nx, 1)), static_cast<float>(std::max(g.ny, 1)),
                                                        static_cast<float>(std::max(g.nz, 1)), probes ? 1.0f : 0.0f));
}

BakedLightView::~BakedLightView() {
    auto& gpm = Ogre::GpuProgramManager::getSingleton();
    const auto& all = gpm.getAvailableSharedParameters();
    if (all.find("ObscuraBakedLight") != all.end())
        gpm.getSharedParameters("ObscuraBakedLight")->setNamedConstant("lightProbeSize", Ogre::Vector4(1, 1, 1, 0));
    auto& tm = Ogre::TextureManager::getSingleton();
    for (auto* t : {&direct_, &indirect_, &probes_})
        if (*t) tm.remove(*t);
}

void BakedLightView::bind(Ogre::Material& material) const {
    for (auto* tech : material.getTechniques())
        for (auto* pass : tech->getPasses()) {
            if (auto* u = pass->getTextureUnitState("lightmapDirect")) u->setTexture(direct_);
            if (auto* u = pass->getTextureUnitState("lightmapIndirect")) u->setTexture(indirect_);
            if (auto* u = pass->getTextureUnitState("lightProbes")) u->setTexture(probes_);
        }
}

}  // namespace obscura::lightbake
