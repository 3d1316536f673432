// Builds a replay script from a live session: key and button presses/releases and mouse motion
// by tick (several motions in one tick merge into one line), plus expected hashes so a playback
// names the first tick where it diverges. Commands may arrive slightly out of tick order (a hash
// for tick t is taken while inputs for t + 1 are already recorded); script() orders them stably.
#pragma once

#include "replay/replay_script.h"

namespace obscura::replay {

class Recorder {
public:
    Recorder(std::string level, std::uint64_t seed, int width, int height, double tickRate);

    // `key` is a key name, or mouse1/mouse2/mouse3 for the left/right/middle buttons.
    void keyDown(std::int64_t tick, const std::string& key);
    void keyUp(std::int64_t tick, const std::string& key);
    void mouse(std::int64_t tick, int dx, int dy);
    // `button` is left, right or middle (anything else throws ScriptError).
    void button(std::int64_t tick, const std::string& button, bool down);
    // A setting the session starts with (the `setting` header: mouse sensitivity, invert, bindings),
    // so a playback reads input the way the recorded session did.
    void setting(const std::string& name, const std::string& value);
    // A setting changed during the session (the pause menu): `<tick> set <name> <value>`.
    void set(std::int64_t tick, const std::string& name, const std::string& value);
    void capture(std::int64_t tick, const std::string& name);
    void hash(std::int64_t tick, const std::string& expected = {});
    void end(std::int64_t tick);

    Script script() const;

private:
    void key(std::int64_t tick, const std::string& key, Command::Action action);
    void add(std::int64_t tick, Command::Type type, const std::string& name, const std::string& value);
    Script script_;
    int mouseIndex_ = -1;  // the mouse command of the latest tick, to merge into
};

}  // namespace obscura::replay
