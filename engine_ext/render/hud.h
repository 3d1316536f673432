// The HUD, drawn with OGRE's ImGui overlay: a crosshair, the frame time, status lines, and a
// debug panel (toggled by a key) to which subsystems add their own sections of knobs.
#pragma once

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
    double frameMs = 0;      // shown as the frame time
    bool frameMsIsFixed = false;  // headless runs show the fixed tick time so captures are repeatable
    std::vector<std::string> status;  // extra lines under the frame time (AO mode, ...)
};

class Hud {
public:
    Hud();
    ~Hud();
    Hud(const Hud&) = delete;
    Hud& operator=(const Hud&) = delete;

    // A section of the debug panel: a title and a function that draws its ImGui widgets.
    void addPanelSection(std::string title, std::function<void()> draw);
    void setPanelVisible(bool v) { panelVisible_ = v; }
    bool panelVisible() const { return panelVisible_; }

    // Builds this frame's UI; call once per frame before rendering.
    void update(const HudState& state);

private:
    void drawPanel();
    Ogre::ImGuiOverlay* overlay_ = nullptr;  // owned by OGRE's OverlayManager once added
    bool panelVisible_ = false;
    std::vector<std::pair<std::string, std::function<void()>>> sections_;
};

}  // namespace obscura::render
