// Player input between the window system and the simulation: key and mouse-button states by
// name, relative mouse motion, and the bindings from Settings turn them into one
// sim::PlayerCommand per tick. Plain C++: live play, recordings and replays feed it the same way.
#pragma once

#include "settings.h"
#include "sim/player_controller.h"

#include <set>
#include <string>
#include <vector>

namespace obscura {

class InputState {
public:
    explicit InputState(const Settings& settings) : settings_(settings) {}

    // `key` is a name from keyNames() ("w", "lshift", "mouse1"...).
    void press(const std::string& key);
    void release(const std::string& key);
    void mouseMotion(int dx, int dy) { mouseDx_ += dx; mouseDy_ += dy; }
    void releaseAll() { down_.clear(); }

    bool isDown(Action a) const;
    bool isKeyDown(const std::string& key) const { return down_.count(key) != 0; }
    // Edge-triggered actions (cycle_ao, toggle_debug, screenshot, menu...) since the last call.
    std::vector<Action> takeTriggered();
    // The command for the next tick; consumes the accumulated mouse motion.
    sim::PlayerCommand takeCommand();

private:
    const Settings& settings_;
    std::set<std::string> down_;
    std::vector<Action> triggered_;
    long mouseDx_ = 0, mouseDy_ = 0;
};

}  // namespace obscura
