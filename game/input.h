// Player input between the window system and the simulation: key and mouse-button states by
// name, relative mouse motion, and the bindings from Settings turn them into one
// sim::PlayerCommand per tick. Plain C++: live play, recordings and replays feed it the same way.
//
// Edges are latched on the event, not sampled at the tick: a key pressed and released between
// two ticks (inside one frame) still reaches the next tick's command as held for that tick, so a
// quick click fires, a tap jumps, reloads, crouches or throws. Modifiers that change what an
// action does (Shift+O) are read when its key goes down, not when the tick handles it.
#pragma once

#include "settings.h"
#include "sim/player_controller.h"

#include <set>
#include <string>
#include <vector>

namespace obscura {

// An edge-triggered action and the modifiers held when its key went down.
struct TriggeredAction {
    Action action;
    bool shift = false;  // lshift or rshift held at the press (Shift+O cycles backwards)
    bool operator==(Action a) const { return action == a; }
};

class InputState {
public:
    explicit InputState(const Settings& settings) : settings_(settings) {}

    // `key` is a name from keyNames() ("w", "lshift", "mouse1"...).
    void press(const std::string& key);
    void release(const std::string& key);
    void mouseMotion(int dx, int dy) { mouseDx_ += dx; mouseDy_ += dy; }
    // Forgets held keys and latched presses (a menu opened over them).
    void releaseAll();

    // Held now, or pressed since the last command.
    bool isDown(Action a) const;
    bool isKeyDown(const std::string& key) const { return down_.count(key) != 0; }
    // Edge-triggered actions (cycle_ao, toggle_debug, screenshot, menu...) since the last call.
    std::vector<TriggeredAction> takeTriggered();
    // The command for the next tick; consumes the accumulated mouse motion and the latched presses.
    sim::PlayerCommand takeCommand();

private:
    const Settings& settings_;
    std::set<std::string> down_;
    std::set<std::string> latched_;  // pressed since the last takeCommand()
    std::vector<TriggeredAction> triggered_;
    long mouseDx_ = 0, mouseDy_ = 0;
};

// Where window input goes while the pause menu or the F1 debug panel is shown (windowed runs;
// headless runs and replays have no pointer to share: everything goes to the game).
struct InputRouting {
    bool menuOpen = false;
    bool panelShown = false;
    bool headless = false;
    // Pointer motion and clicks: to the menu / panel (no shots, no turning), else to the game.
    bool mouseToUi() const { return !headless && (menuOpen || panelShown); }
    // Keys: the menu takes them (only its own key reaches the game); the panel leaves them.
    bool keysToUi() const { return !headless && menuOpen; }
    // The window keeps the pointer (relative mouse) only while the game has it.
    bool grabPointer() const { return !headless && !mouseToUi(); }
};

}  // namespace obscura
