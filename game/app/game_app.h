// The game's OGRE/SDL glue (through OgreBites): window or headless render target, resources,
// RTSS, level rendering, HUD, input, and the fixed-tick main loop. The game owns the simulation
// and pushes its state to rendering one way; nothing here feeds render state back into it.
#pragma once

#include "input.h"
#include "replay_player.h"
#include "settings.h"

#include <OgreApplicationContext.h>
#include <OgreInput.h>

#include <memory>
#include <string>

namespace OgreBites { struct ImGuiInputListener; }
namespace Ogre {
class Camera;
class RenderTexture;
class SceneManager;
class SceneNode;
class Viewport;
}  // namespace Ogre

namespace obscura {
namespace map { struct Level; }
namespace sim { class Simulation; struct PlayerState; }
namespace render { class Hud; class LevelGeometry; class LevelMaterials; class PropView; }
namespace replay { struct Script; class Recorder; }
namespace ssao { class AmbientOcclusion; }
namespace frame { class Frame; }
class CombatView;
class GameAudio;
class GameSmoke;
class PauseMenu;

class GameApp : public OgreBites::ApplicationContext, public OgreBites::InputListener {
public:
    GameApp(Settings settings, const SettingsParser& parser);
    ~GameApp() override;

    // Runs the game until quit or --ticks; returns the process exit code. Throws on load errors.
    int run();

protected:
    // OgreBites::ApplicationContext: no plugins.cfg, no config dialog, our own resources.
    void createRoot() override;
    bool oneTimeConfig() override;
    void setup() override;
    void locateResources() override;
    void shutdown() override;

    // OgreBites::InputListener
    bool keyPressed(const OgreBites::KeyboardEvent& evt) override;
    bool keyReleased(const OgreBites::KeyboardEvent& evt) override;
    bool mouseMoved(const OgreBites::MouseMotionEvent& evt) override;
    bool mousePressed(const OgreBites::MouseButtonEvent& evt) override;
    bool mouseReleased(const OgreBites::MouseButtonEvent& evt) override;
    bool mouseWheelRolled(const OgreBites::MouseWheelEvent& evt) override;

private:
    void prepareReplay();
    int runLive();
    int runReplay(bool timed);
    void injectInput(const ReplayInput& in);
    void onButton(const std::string& name, bool down);
    void applySetting(const std::string& key, const std::string& value, const std::string& where);
    void writeCapture(const std::string& name);
    void writeRecording();
    std::string rendererDescription() const;
    void loadLevel();
    void createScene();
    void stepSimulation();
    void updateView(double alpha);
    void handleTriggeredActions();
    void renderFrame(double frameMs);
    void writeScreenshot(const std::string& path);
    void finishFrame();
    std::string dataPath(const std::string& relative) const;

    Settings settings_;
    const SettingsParser& parser_;
    InputState input_;

    std::unique_ptr<map::Level> level_;
    std::unique_ptr<sim::Simulation> sim_;
    std::unique_ptr<sim::PlayerState> previousPlayer_;  // for render interpolation

    Ogre::SceneManager* scene_ = nullptr;
    Ogre::Camera* camera_ = nullptr;
    Ogre::SceneNode* cameraNode_ = nullptr;
    Ogre::Viewport* viewport_ = nullptr;
    Ogre::TexturePtr offscreen_;  // headless render target
    std::unique_ptr<render::LevelMaterials> materials_;
    std::unique_ptr<render::LevelGeometry> levelGeometry_;
    std::unique_ptr<render::PropView> props_;
    std::unique_ptr<render::Hud> hud_;
    std::unique_ptr<ssao::AmbientOcclusion> ao_;
    std::unique_ptr<frame::Frame> frame_;  // the pass order; ao_ and smoke_'s technique plug into it
    void applyAoSettings();
    std::string aoStatus() const;
    std::unique_ptr<GameAudio> audio_;
    std::unique_ptr<CombatView> combat_;
    std::unique_ptr<GameSmoke> smoke_;
    std::unique_ptr<PauseMenu> menu_;
    std::unique_ptr<OgreBites::ImGuiInputListener> imguiInput_;  // the menu's mouse and keys
    bool menuTakesInput() const;
    void setMenuOpen(bool open);
    void resizeWindow(int width, int height);
    double hitMarker_ = 0;  // HUD hit marker, 1 at a hit, fading per tick

    std::unique_ptr<replay::Script> script_;      // --replay / --timedemo
    std::unique_ptr<replay::Recorder> recorder_;  // --record

    bool quit_ = false;
    bool mouseGrabbed_ = false;
};

}  // namespace obscura
