// See decal_render.h.
#include "decals/decal_render.h"

#include "frame/frame_shared.h"

#include <Ogre.h>
#include <OgreCompositionTechnique.h>

#include <algorithm>
#include <iostream>

namespace obscura::decals {

namespace {
// The boxes' render queue: after the effects (80-89), before the overlays; only the decals
// stage's scene pass (media/decals/decals.compositor) draws it.
constexpr Ogre::uint8 kDecalQueue = 90;
const char* const kMaterial = "Obscura/Decals/Box";
const char* const kAtlas = "decal_atlas.png";

// The build's atlas with `signs` laid after it: one RGBA image, mipmapped by OGRE like the file.
Ogre::TexturePtr atlasWithSigns(const Image& signs) {
    Ogre::Image file;
    file.load(kAtlas, Ogre::RGN_DEFAULT);
    const Ogre::uint32 w = file.getWidth() + static_cast<Ogre::uint32>(signs.width), h = DECAL_TILE;
    if (file.getHeight() != h || signs.height != DECAL_TILE)
        throw std::runtime_error(std::string("decals: ") + kAtlas + " is not " + std::to_string(DECAL_TILE) + " texels high");
    std::vector<Ogre::uchar> rgba(static_cast<std::size_t>(w) * h * 4);
    Ogre::PixelBox all(w, h, 1, Ogre::PF_BYTE_RGBA, rgba.data());
    Ogre::PixelUtil::bulkPixelConversion(file.getPixelBox(), all.getSubVolume(Ogre::Box(0, 0, file.getWidth(), h)));
    for (Ogre::uint32 y = 0; y < h; ++y)
        std::copy_n(signs.rgba.begin() + static_cast<std::ptrdiff_t>(y) * signs.width * 4, signs.width * 4,
                    rgba.begin() + (static_cast<std::ptrdiff_t>(y) * w + file.getWidth()) * 4);
    Ogre::Image image;
    image.loadDynamicImage(rgba.data(), w, h, Ogre::PF_BYTE_RGBA);
    return Ogre::TextureManager::getSingleton().loadImage("Obscura/Decals/AtlasWithSigns", Ogre::RGN_DEFAULT, image);
}
}  // namespace

DecalRender::DecalRender(Ogre::SceneManager& scene, int capacity, const Image& signTiles) : scene_(scene), capacity_(std::max(capacity, 1)) {
    auto& rgm = Ogre::ResourceGroupManager::getSingleton();
    material_ = Ogre::MaterialManager::getSingleton().getByName(kMaterial);
    if (!rgm.resourceExistsInAnyGroup("decal_atlas.png") || !material_) {
        std::cerr << "obscura: decals: off: " << (material_ ? "the atlas decal_atlas.png (built by tools/decalbake)"
                                                            : std::string("material ") + kMaterial + " (media/decals/decals.material)")
                  << " is missing\n";
        material_.reset();
        return;
    }
    data_ = Ogre::TextureManager::getSingleton().createManual(
        "Obscura/Decals/Data", Ogre::RGN_DEFAULT, Ogre::TEX_TYPE_2D, DECAL_TEXELS, static_cast<Ogre::uint>(capacity_), 0,
        Ogre::PF_FLOAT32_RGBA, Ogre::TU_DYNAMIC_WRITE_ONLY);
    material_->load();
    Ogre::Pass* pass = material_->getTechnique(0)->getPass(0);
    if (Ogre::TextureUnitState* u = pass->getTextureUnitState("decalData")) u->setTexture(data_);
    // The atlas: the build's file, or it and the level's signs (the material is shared by every
    // session: set both ways).
    if (signTiles.width > 0) atlas_ = atlasWithSigns(signTiles);
    if (Ogre::TextureUnitState* u = pass->getTextureUnitState("decalAtlas")) {
        if (atlas_) u->setTexture(atlas_);
        else u->setTextureName(kAtlas);
    }
    pass->getFragmentProgramParameters()->setNamedConstant(
        "atlasTiles", static_cast<float>(DECAL_TILES + (atlas_ ? signTiles.width / DECAL_TILE : 0)));
    boxes_ = scene_.createManualObject("Obscura/Decals/Boxes");
    boxes_->setDynamic(true);
    boxes_->setCastShadows(false);
    boxes_->setRenderQueueGroup(kDecalQueue);
    node_ = scene_.getRootSceneNode()->createChildSceneNode();
    node_->attachObject(boxes_);
    usable_ = true;
}

DecalRender::~DecalRender() {
    if (boxes_) {
        node_->detachAllObjects();
        scene_.destroySceneNode(node_);
        scene_.destroyManualObject(boxes_);
    }
    if (atlas_ && material_)
        if (Ogre::TextureUnitState* u = material_->getTechnique(0)->getPass(0)->getTextureUnitState("decalAtlas"))
            u->setTextureName(kAtlas);
    material_.reset();
    if (data_) Ogre::TextureManager::getSingleton().remove(data_);
    if (atlas_) Ogre::TextureManager::getSingleton().remove(atlas_);
}

std::string DecalRender::compositor() const { return usable_ ? "Obscura/Decals/Boxes" : std::string(); }

std::string DecalRender::missingFeature(const frame::Gpu& gpu) const {
    split_ = gpu.renderTargets < FRAME_GBUFFER_TARGETS;
    return {};
}

void DecalRender::configure(Ogre::CompositionTechnique&) const {
    // The boxes' material reads the G-buffer from its compositor (content_type compositor).
    Ogre::Pass* pass = material_->getTechnique(0)->getPass(0);
    auto ref = [&](const char* unit, int slot) {
        if (Ogre::TextureUnitState* u = pass->getTextureUnitState(unit)) {
            if (split_)
                u->setCompositorReference("Obscura/Frame/GBufferSplit", slot < FRAME_GBUFFER_SPLIT ? "gbufferA" : "gbufferB",
                                          slot < FRAME_GBUFFER_SPLIT ? slot : slot - FRAME_GBUFFER_SPLIT);
            else u->setCompositorReference("Obscura/Frame/GBuffer", "gbuffer", slot);
        }
    };
    ref("gbufferDepth", FRAME_GBUFFER_DEPTH);
    ref("gbufferNormal", FRAME_GBUFFER_NORMAL);
}

void DecalRender::update(const std::vector<Decal>& decals, std::uint64_t version) {
    if (!usable_ || version == uploaded_) return;
    uploaded_ = version;
    const std::size_t count = std::min(decals.size(), static_cast<std::size_t>(capacity_));
    const std::vector<Decal> slots(decals.begin(), decals.begin() + static_cast<std::ptrdiff_t>(count));
    // The data texture: one row a decal.
    std::vector<float> texels(static_cast<std::size_t>(DECAL_TEXELS) * 4 * capacity_, 0.0f);
    for (std::size_t i = 0; i < slots.size(); ++i) {
        const auto p = packDecal(slots[i]);
        std::copy(p.begin(), p.end(), texels.begin() + static_cast<std::ptrdiff_t>(i * p.size()));
    }
    data_->getBuffer()->blitFromMemory(
        Ogre::PixelBox(DECAL_TEXELS, static_cast<Ogre::uint32>(capacity_), 1, Ogre::PF_FLOAT32_RGBA, texels.data()));
    // The boxes: 8 corners each, uv0.x = the slot.
    boxes_->clear();
    if (slots.empty()) return;
    boxes_->estimateVertexCount(slots.size() * 8);
    boxes_->estimateIndexCount(slots.size() * 36);
    boxes_->begin(kMaterial, Ogre::RenderOperation::OT_TRIANGLE_LIST);
    static const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (std::size_t i = 0; i < slots.size(); ++i) {
        const Decal& d = slots[i];
        const auto p = packDecal(d);
        // Box corners in the world: centre + (+-1) * axis * half (the rows are axis / half).
        Ogre::Vector3 axes[3];
        for (int r = 0; r < 3; ++r) {
            const Ogre::Vector3 a(p[r * 4], p[r * 4 + 1], p[r * 4 + 2]);
            axes[r] = a / a.squaredLength();
        }
        const Ogre::Vector3 c(static_cast<float>(d.position.x), static_cast<float>(d.position.y), static_cast<float>(d.position.z));
        for (int k = 0; k < 8; ++k) {
            boxes_->position(c + axes[0] * ((k & 1) ? 1.f : -1.f) + axes[1] * ((k & 2) ? 1.f : -1.f) + axes[2] * ((k & 4) ? 1.f : -1.f));
            boxes_->textureCoord(static_cast<float>(i), 0.f);
        }
        const Ogre::uint32 base = static_cast<Ogre::uint32>(i * 8);
        for (const auto& f : faces) {
            boxes_->quad(base + f[0], base + f[1], base + f[2], base + f[3]);
        }
    }
    boxes_->end();
}

}  // namespace obscura::decals
