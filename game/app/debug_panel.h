// The F1 debug panel (ImGui, drawn by the HUD): the player's tick, position and speed, the AO mode
// and knobs, the level's batch and light counts. It reads the session and the view; knob changes
// go back through the game (`aoChanged`), which applies them to the view as any setting.
#pragma once

#include "settings.h"

#include <functional>

namespace obscura {

class RenderView;
class Session;

class DebugPanel {
public:
    // Adds the panel's sections to view.hud(). `settings` holds the knobs the sliders edit;
    // `aoChanged` is called after one changed.
    DebugPanel(RenderView& view, const Session& session, Settings& settings, std::function<void()> aoChanged);

    bool visible() const;
    void setVisible(bool on);

private:
    void drawPlayer() const;
    void drawAo();
    void drawLevel() const;

    RenderView& view_;
    const Session& session_;
    Settings& settings_;
    std::function<void()> aoChanged_;
};

}  // namespace obscura
