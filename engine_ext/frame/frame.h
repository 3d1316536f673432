// The frame as a list of passes (Quake III's CG_DrawActiveFrame in spirit). Its order is written
// once, in media/frame/frame.compositor and in Frame::plan():
//   shadow maps (OGRE texture shadows, drawn by the G-buffer's scene pass)
//   -> G-buffer (the scene once, unlit: frame_shared.h)  -> decals  -> AO
//   -> lighting (albedo x (direct + ambient x AO), HDR) and the effects queue added into it
//   -> volumetrics (smoke)  -> output (volumes over the light, exposure, one tone map)  -> HUD
// Techniques (technique.h) are added by the game and sit where their stage says; the frame binds
// what they publish (aoMap, volumeMap) and what it owns (gbufferAlbedo, gbufferNormal,
// gbufferDepth, gbufferLight, litMap) to any texture unit of that name in any pass. A technique
// that cannot run here (a GPU feature missing, a uniform its program lacks) is turned off with one
// stderr line naming it, and the rest of the frame goes on.
#pragma once

#include "frame/technique.h"

#include <OgreMaterialManager.h>
#include <OgreVector.h>
#include <OgreRenderQueue.h>
#include <OgreTexture.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace Ogre {
class Viewport;
}

namespace obscura::frame {

// Translucent liquids (engine_ext/render/level_geometry.cpp) and then additive effects (muzzle
// flash, sparks) are in these queues: drawn into the HDR light after the lighting pass, liquids
// first so a flash above the water glows over its surface; the G-buffer's scene pass stops before
// them (media/frame/frame.compositor: queues 80-89 after lighting).
constexpr Ogre::uint8 kLiquidQueue = Ogre::RENDER_QUEUE_8;
constexpr Ogre::uint8 kEffectsQueue = Ogre::RENDER_QUEUE_8 + 1;

struct FrameSettings {
    int maxRenderTargets = 0;                     // pretend the GPU has at most this many; 0: its own
    std::vector<std::string> unsupportedFormats;  // pretend these render-target formats are missing
    float exposure = 1.6f;
};


// A box in which the lighting pass scales the ambient light (a level's env_ambient: map::AmbientArea).
struct AmbientBox {
    Ogre::Vector3 min, max;  // world
    float scale = 1;         // the ambient times this inside
    float blend = 0;         // metres across the faces, centred on them; 0 = a hard edge
};

class Frame : public Ogre::MaterialManager::Listener {
public:
    Frame(Ogre::Viewport& viewport, Ogre::Camera& camera, FrameSettings settings);
    ~Frame() override;
    Frame(const Frame&) = delete;
    Frame& operator=(const Frame&) = delete;

    // A technique the game made (not owned; it must outlive the frame).
    void add(Technique& technique);
    void setExposure(float exposure) { settings_.exposure = exposure; }
    // The boxes the ambient is scaled in, at most FRAME_MAX_AMBIENT_AREAS (frame_shared.h): the
    // rest are dropped (the caller warns).
    void setAmbientAreas(std::vector<AmbientBox> areas);
    // A scene material drawn after lighting that reads the frame's buffers (liquids read the
    // G-buffer's depth: they test against it in their shader, the depth buffer of `lit` not being
    // the G-buffer's on every driver): its texture units named like a published buffer
    // (gbufferDepth, ...) are bound at every rebuild. The material must outlive the frame.
    void addSceneMaterial(const Ogre::MaterialPtr& material);
    // What the frame shows: "scene", "ao" (the AO alone), or a technique's debug view.
    std::vector<std::string> views() const;
    void setView(const std::string& view);
    const std::string& view() const { return view_; }
    // Rebuilds the chain when a technique's compositor or configuration changed. Call once a
    // frame before rendering (never from inside a render).
    void update(float time);
    // A buffer as the passes read it (gbufferDepth, litMap, volumeMap, ...: publish()); null before
    // the chain is built or when no pass of that name runs (a 1x1 stand-in is then bound instead:
    // `standIn` true). flipY: the buffers are render textures stored upside down.
    Ogre::TexturePtr published(const std::string& unit, bool* standIn = nullptr) const;
    bool flipY() const { return context_.flipY; }
    // Why the technique's stage was turned off here for its current configuration; empty if not.
    std::string offReason(const Technique& technique) const;

    // Ogre::MaterialManager::Listener: the G-buffer fallback for materials without a GBuffer technique.
    Ogre::Technique* handleSchemeNotFound(unsigned short schemeIndex, const Ogre::String& schemeName,
                                          Ogre::Material* originalMaterial, unsigned short lodIndex,
                                          const Ogre::Renderable* rend) override;

    // Before a capture: rewinds the volumetrics' phase to its cycle's start and returns the frames
    // to draw of the unchanged scene (FRAME_VOLUME_PHASES; 0 while nothing is marched), after which
    // they show converged and the same whatever frames came before, or how many (every pixel
    // marched once on this state, then clamped in one order).
    int settleVolumes();

private:
    struct Entry;
    class Binder;
    std::vector<std::unique_ptr<Entry>> plan() const;
    std::string key() const;
    void rebuild();
    void removeAll();
    bool instance(Entry& e);
    void publish();
    void turnOff(const Technique& t, const std::string& reason);
    void setupPass(Entry& e, Ogre::uint32 passId, Ogre::Material& mat);
    void renderPass(Entry& e, Ogre::uint32 passId, Ogre::Material& mat);
    void bind(Entry& e, Ogre::uint32 passId, Ogre::Pass& pass, Uniforms& u);

    Ogre::Viewport& viewport_;
    Ogre::Camera& camera_;
    FrameSettings settings_;
    std::vector<AmbientBox> ambientAreas_;
    Gpu gpu_;
    std::string view_ = "scene";
    std::vector<std::unique_ptr<Technique>> own_;  // the frame's debug techniques (gbuffer_view)
    std::vector<Technique*> techniques_;
    std::vector<std::unique_ptr<Entry>> chain_;
    std::string builtKey_;
    std::map<const Technique*, std::pair<std::string, std::string>> off_;  // configuration key -> reason
    std::map<std::string, Ogre::TexturePtr> published_;  // texture-unit name -> texture
    std::vector<Ogre::MaterialPtr> sceneMaterials_;       // addSceneMaterial
    void bindSceneMaterial(Ogre::Material& material);
    Ogre::TexturePtr noAo_, noVolume_, noDecals_;  // bound while no AO / no volumes / no decals run
    Ogre::MaterialPtr gbufferFallback_;
    bool split_ = false;  // the G-buffer in two passes (fewer than FRAME_GBUFFER_TARGETS targets)
    Ogre::Technique* addPart(Ogre::Material& material, const Ogre::Technique& gbuffer, int part);
    FrameContext context_;
    // The volumetrics' interleaved march (shaders/frame/volume_resolve.frag): frames resolved
    // since the chain was built (the phase, whether a history exists) and the view they were seen from.
    std::uint64_t volumeFrames_ = 0;
    Ogre::Matrix4 volumeLastView_ = Ogre::Matrix4::IDENTITY;
};

}  // namespace obscura::frame
