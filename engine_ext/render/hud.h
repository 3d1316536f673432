// The HUD, drawn with OGRE's ImGui overlay: a crosshair (with a hit marker), ammo, score, the
// grenade throw charge, the frame time and its graph, status lines (the AO mode), and a debug
// panel (toggled by a key) to which subsystems add their own sections of knobs.
#pragma once

#include <deque>
#include <functional>
#include <string>
#include <vector>

namespace Ogre {
class ImGuiOverlay;
class SceneManager;
class OverlaySystem;
}  // namespace Ogre

namespace obscura::render {

struct HudState {
    bool visible = true;     // crosshair and text (the debug panel follows its own toggle)
    bool crosshair = true;   // off while a menu is open
    double frameMs = 0;      // shown as the frame time
    bool frameMsIsFixed = false;  // headless runs show the fixed tick time so captures are repeatable
    std::vector<std::string> status;  // extra lines under the frame time (AO mode, ...)
    // Combat (absent: magazineSize 0)
    int magazine = 0, magazineSize = 0, reserve = 0;
    double reloadProgress = -1;  // 0..1 while reloading, else < 0
    int score = 0;
    double hitMarker = 0;        // 1 just after a hit, fading to 0
    double throwCharge = -1;     // 0..1 while the grenade key is held, else < 0
    std::string centreMessage;   // a level's `message` (lines split at '\n'), centred above the crosshair; empty: none
};

class Hud {
public:
    Hud();
    ~Hud();
    Hud(const Hud&) = delete;
    Hud& operator=(const Hud&) = delete;

    // A section of the debug panel: a title and a function that draws its ImGui widgets.
    void addPanelSection(std::string title, std::function<void()> draw);
    // A window drawn every frame after the HUD (the pause menu); it decides itself when to show.
    void setMenu(std::function<void()> draw) { menu_ = std::move(draw); }
    void setPanelVisible(bool v) { panelVisible_ = v; }
    bool panelVisible() const { return panelVisible_; }

    // Builds this frame's UI; call once per frame before rendering.
    void update(const HudState& state);
    // A frame not drawn (a replay's frame no capture reads) still takes its bar in the frame-time
    // graph, so the graph a capture shows does not depend on which frames were drawn.
    void recordFrame(double frameMs);

private:
    void drawPanel();
    void drawCombat(const HudState& state);
    void drawCentreMessage(const std::string& text);
    void drawFrameGraph();
    Ogre::ImGuiOverlay* overlay_ = nullptr;  // owned by OGRE's OverlayManager once added
    bool panelVisible_ = false;
    std::deque<float> frameHistory_;
    std::function<void()> menu_;  // the last kFrameHistory frame times, ms
    std::vector<std::pair<std::string, std::function<void()>>> sections_;
};

}  // namespace obscura::render
