// The frame's decals stage (engine_ext/frame/technique.h): every decal's box drawn (back faces,
// one batch) into the decal buffer `decals` (RGBA8: premultiplied albedo in gamma, coverage),
// against the G-buffer's depth and normal; the lighting pass lays it over the albedo
// (unit decalAlbedo). Decal parameters live in a small float texture, one row a decal.
#pragma once

#include "core/image.h"
#include "decals/decal_list.h"
#include "frame/technique.h"

#include <OgreMaterial.h>
#include <OgreTexture.h>

namespace Ogre {
class ManualObject;
class SceneManager;
class SceneNode;
}  // namespace Ogre

namespace obscura::decals {

class DecalRender : public frame::Technique {
public:
    // Off (one stderr line, the frame goes on) when the atlas or the material is missing.
    // capacity: the most decals update() is given (rows of the data texture). signTiles: the
    // level's sign tiles (DECAL_TILE * n x DECAL_TILE RGBA, n <= DECAL_MAX_TILES - DECAL_TILES),
    // laid after the build's atlas in a texture made here; empty: the build's atlas alone.
    DecalRender(Ogre::SceneManager& scene, int capacity, const Image& signTiles = {});
    ~DecalRender() override;
    DecalRender(const DecalRender&) = delete;
    DecalRender& operator=(const DecalRender&) = delete;

    // Once a frame before rendering: the boxes and the data texture follow `decals` (the game's
    // list, decal_attach.h), uploaded when `version` moved; decals beyond the capacity are left
    // out.
    void update(const std::vector<Decal>& decals, std::uint64_t version);

    // frame::Technique
    std::string folder() const override { return "engine_ext/decals"; }
    frame::Stage stage() const override { return frame::Stage::Decals; }
    std::string compositor() const override;
    std::string missingFeature(const frame::Gpu& gpu) const override;
    void configure(Ogre::CompositionTechnique&) const override;
    void bind(Ogre::uint32, Ogre::Pass&, frame::Uniforms&, const frame::FrameContext&) override {}
    std::vector<Output> outputs() const override { return {{"decals", "decalAlbedo", 0}, {"decals", "decalNormal", 1}}; }

private:
    Ogre::SceneManager& scene_;
    int capacity_;
    std::uint64_t uploaded_ = ~0ull;
    bool usable_ = false;
    mutable bool split_ = false;  // the G-buffer split in two (fewer than 4 targets): other names
    Ogre::MaterialPtr material_;
    Ogre::TexturePtr data_;
    Ogre::TexturePtr atlas_;  // the build's atlas and the signs' tiles; null without signs
    Ogre::ManualObject* boxes_ = nullptr;
    Ogre::SceneNode* node_ = nullptr;
};

}  // namespace obscura::decals
