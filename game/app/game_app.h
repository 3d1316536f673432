// The game: OgreBites' application context (window or hidden window, resources, RTSS), the
// window's input, and the pieces it wires together one way: the Session (level, simulation,
// smoke; plain C++) advanced tick by tick from the input, the RenderView, sound, the pause menu
// and the debug panel reading it. Every run mode goes through the one frame loop
// (app/run_driver.h) with its own driver; nothing feeds render state back into the simulation.
#pragma once

#include "app/replay_driver.h"
#include "app/run_driver.h"
#include "input.h"
#include "settings.h"

#include <OgreApplicationContext.h>
#include <OgreInput.h>

#include <array>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace OgreBites { struct ImGuiInputListener; }

namespace obscura {
namespace replay { struct Script; class Recorder; }
class DebugPanel;
class GameAudio;
class PauseMenu;
class RenderView;
class Session;

class GameApp : public OgreBites::ApplicationContext,
                public OgreBites::InputListener,
                private FrameHost,
                private ReplayHost {
public:
    GameApp(Settings settings, const SettingsParser& parser);
    ~GameApp() override;

    // Runs the game until quit, --ticks, the replay's end or a stop signal; returns the process
    // exit code. Throws on load errors.
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
    // FrameHost
    void pollEvents() override { OgreBites::ApplicationContext::pollEvents(); }
    void handleActions() override;
    void tick() override;
    void present(double alpha, double frameMs) override;
    void skipDraw(double alpha, double frameMs) override;
    bool paused() const override;
    bool interfaceOpen() const override;
    bool quitRequested() const override;
    std::uint64_t simTick() const override;
    // ReplayHost
    void applySetting(const std::string& key, const std::string& value, const std::string& where) override;
    void injectInput(const ReplayInput& in) override;
    void writeScreenshot(const std::string& path) override;
    void finishFrame() override;
    std::string stateHashHex() const override;
    std::string cameraPose() const override;
    double smokeRenderThreadMs() const override;

    void load();
    void followState(double alpha);  // a frame's view of the state, drawn or not: camera, props, the listener
    void applyAoSettings();
    void onButton(const std::string& name, bool down);
    InputRouting routing() const;
    void setMenuOpen(bool open);
    void setPanelVisible(bool visible);
    void updatePointerGrab();
    void afterUiFrame();  // releases held back for ImGui (mouseReleased)
    void changeLevel(const map::LevelEntity& trigger);  // game_app_level.cpp
    void resizeWindow(int width, int height);
    void writeRecording();
    std::string rendererDescription() const;
    std::string dataPath(const std::string& relative) const;
    std::string summaryLine() const;
    std::string notice() const;  // the HUD's notice line while it lasts, else empty
    std::size_t signHoles() const;

    Settings settings_;
    const SettingsParser& parser_;
    InputState input_;

    std::unique_ptr<Session> session_;
    std::string notice_;                 // the last F12's news for the HUD
    std::uint64_t noticeUntilTick_ = 0;  // shown until this simulation tick
    std::unique_ptr<RenderView> view_;
    std::unique_ptr<GameAudio> audio_;
    std::unique_ptr<PauseMenu> menu_;
    std::unique_ptr<DebugPanel> panel_;
    std::unique_ptr<OgreBites::ImGuiInputListener> imguiInput_;  // the menu's and the panel's mouse and keys
    std::set<unsigned char> uiPressedUnseen_;                    // UI buttons pressed since the last UI frame
    std::vector<OgreBites::MouseButtonEvent> uiReleasesDue_;     // their releases, held for the next frame

    std::unique_ptr<replay::Script> script_;      // --replay / --timedemo
    std::unique_ptr<replay::Recorder> recorder_;  // --record

    // What the player did this run, counted from the simulation's events (fire, jump, reload,
    // throw): printed at exit as the `summary` line that scripts driving a window read.
    std::array<std::uint64_t, 4> tally_{};

    bool quit_ = false;
    bool mouseGrabbed_ = false;
};

}  // namespace obscura
