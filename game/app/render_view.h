// What the player sees, and nothing else: the OGRE scene (level geometry, the visible misc_models,
// props, targets and combat effects), the camera, the frame pipeline (engine_ext/frame) with its
// techniques (ambient occlusion, the smoke's ray-march) and the HUD. It reads a Session one way —
// every frame it is told the state to show — and never feeds anything back into the simulation.
#pragma once

#include "core/vec3.h"
#include "map/liquid.h"
#include "settings.h"
#include "sim/sim_events.h"

#include <OgrePrerequisites.h>
#include <OgreAxisAlignedBox.h>
#include <OgreTexture.h>

#include <memory>
#include <string>
#include <vector>

namespace Ogre {
class OverlaySystem;
class RenderWindow;
namespace RTShader { class ShaderGenerator; }
}  // namespace Ogre

namespace obscura {
namespace render { class Hud; class LevelGeometry; class LevelMaterials; class PropView; struct LevelGeometryStats; }
namespace frame { class Frame; }
namespace lightbake { class BakedLightView; }
namespace smoke { class SmokeRender; }
namespace signs { class SignRender; }
namespace ssao { class AmbientOcclusion; }
namespace decals { class DecalRender; }
class CombatView;
class Session;
class TruthKey;

class RenderView {
public:
    // What OGRE's application context owns and the view draws with.
    struct Context {
        Ogre::Root& root;
        Ogre::RenderWindow& window;
        Ogre::OverlaySystem& overlays;
        Ogre::RTShader::ShaderGenerator& shaders;
    };
    // The AO settings the view shows (game/settings.h has their meaning and defaults).
    struct AoSettings {
        std::string mode;
        double radius = 0, largeRadius = 0, intensity = 0;
        int samples = 0;
        double resolution = 1;
        bool aoOnly = false;
        double exposure = 1;
    };
    static AoSettings aoSettings(const Settings& settings);
    // One frame's HUD facts the session does not hold.
    struct Frame {
        double frameMs = 0;
        bool frameMsIsFixed = false;  // headless: the fixed tick time, so captures repeat
        bool hudVisible = true;
        bool crosshair = true;        // off while the menu is open
        std::string notice;           // a line of the game's own news (where F12 wrote), under the status lines
    };
    // The camera, for the sound's listener (metres, world space).
    struct Listener {
        Vec3 position, forward, up;
    };

    // Builds the scene for `session`'s level (headless: into an offscreen texture of
    // settings.width x height) and applies the AO settings. Throws at load time.
    RenderView(const Context& context, const Settings& settings, const Session& session);
    ~RenderView();
    RenderView(const RenderView&) = delete;
    RenderView& operator=(const RenderView&) = delete;

    // The frame's knobs: AO mode and knobs, the AO-only view, the exposure. A mode this GPU cannot
    // run is turned off by the frame at the next frame, with one line on stderr.
    void applyAo(const AoSettings& ao);
    // The AO mode as the HUD and the panel say it ("horizon", "horizon (off here)").
    std::string aoStatus() const;
    // The next of the frame's views (scene, ao, the G-buffer's ...); returns it.
    std::string cycleView();

    // The AO truth key (app/truth_key.h): what is shown ("off", "reference", "mode", "heatmap",
    // settings.truth) and the reference's rays per pixel.
    void setTruth(const std::string& show, int rays);
    bool truthShown() const;
    // Frames to draw before a capture so the volumetrics show converged (frame::Frame::settleVolumes).
    int settleVolumes();
    // Headless captures: waits for the reference (the next two frames then show and score it).
    void waitTruth() const;

    // Camera: horizontal field of view (degrees); a resized window's new aspect.
    void setFov(double horizontalDegrees);
    // The back-lit signs: "off", "shafts" or "meshuggah", and the haze per metre (settings.signMode, signHaze).
    void setSigns(const std::string& mode, double haze);
    void resized(int width, int height, double horizontalFov);

    // After each simulation tick: effects for its events.
    void onTick(const std::vector<sim::SimEvent>& events);
    double smokeUploadMs() const;  // the smoke's uploads in the last update()
    // Once a frame: the camera between the previous and the latest tick (alpha 0..1), props, targets.
    void update(const Session& session, double alpha);
    Listener listener() const;
    // Once a frame: the HUD, the smoke's fields, then OGRE renders the frame.
    void draw(const Session& session, const Frame& frame);
    // Instead of draw() in a frame nobody sees: only the HUD's frame-time graph takes the frame
    // (the smoke's, decals' and signs' latest state goes up at the next draw()).
    void skipDraw(const Frame& frame);
    // Waits for the frame's rendering (timed frames include their own GPU work).
    void finishFrame();
    void writeScreenshot(const std::string& path);  // throws (load-time callers: --screenshot, captures)
    // The last frame's HDR buffers as PFM (core/pfm.h) for tools/signref: `volumeMap` (the
    // volumetric pass's in-scattered light, half resolution; zeros when nothing was marched) and
    // `litMap` (the surfaces' light before the volumes, full resolution). Throws naming the file.
    // The G-buffer's direct + ambient irradiance (before AO and albedo) as a PFM (tools/lightref).
    void writeIrradianceDump(const std::string& path);
    void writeBufferDump(const std::string& unit, const std::string& path);
    std::string saveScreenshot(const std::string& path) noexcept;  // in the frame (F12): the problem, or empty

    render::Hud& hud() { return *hud_; }
    const render::LevelGeometryStats& levelStats() const;

private:
    Ogre::RenderTarget& target();
    // A texture's texels as float RGBA, the picture's top row first.
    std::vector<float> readRgba(const Ogre::TexturePtr& tex) const;
    // Bakes the AO height map again when the movers rest elsewhere than at the last bake and the
    // heightfield mode (the one that reads it) is on.
    void rebakeHeightMapIfStale();

    Ogre::Root& root_;
    Ogre::RenderWindow& window_;
    Ogre::OverlaySystem& overlays_;
    Ogre::RTShader::ShaderGenerator& shaders_;
    Ogre::SceneManager* scene_ = nullptr;
    Ogre::Camera* camera_ = nullptr;
    Ogre::SceneNode* cameraNode_ = nullptr;
    Ogre::Viewport* viewport_ = nullptr;
    Ogre::TexturePtr offscreen_;  // headless render target
    Vec3 eye_;
    map::LiquidQuery liquids_;  // where the camera is under water, slime or lava (the tint and fog)
    std::unique_ptr<render::LevelMaterials> materials_;
    std::unique_ptr<render::LevelGeometry> levelGeometry_;
    std::unique_ptr<lightbake::BakedLightView> bakedLight_;
    std::unique_ptr<render::PropView> props_;
    std::unique_ptr<ssao::AmbientOcclusion> ao_;
    std::unique_ptr<smoke::SmokeRender> smoke_;
    std::unique_ptr<decals::DecalRender> decals_;
    std::unique_ptr<signs::SignRender> signs_;
    std::unique_ptr<frame::Frame> frame_;  // the pass order; ao_, decals_ and smoke_ plug into it
    std::unique_ptr<CombatView> combat_;
    std::unique_ptr<render::Hud> hud_;
    std::unique_ptr<TruthKey> truth_;  // plugs a pass into frame_
    double yaw_ = 0, pitch_ = 0, fov_ = 90, aoRadius_ = 0;  // the camera as drawn (radians, degrees), the AO radius
    Ogre::AxisAlignedBox heightBounds_;  // the AO height map's box (null: no brushes)
    std::string aoMode_;
    std::vector<Vec3> bakedMoverOffsets_, latestMoverOffsets_;  // sim().movers() order
    bool heightMapStale_ = false;
};

}  // namespace obscura
