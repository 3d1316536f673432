// Plays a replay script (engine_ext/replay) tick by tick: turns its commands into the input
// events, setting changes, captures and hash checks due at each tick. Plain C++; the OGRE/SDL
// glue injects the input events as real SDL events so they take the same path as a keyboard.
//
// Tick semantics: commands at tick t act before simulation step t; `capture` and `hash` at tick t
// act on the state after step t and the frame rendered from it. A `key ... tap` presses at t and
// releases at t + 1. The script's `setting` headers come first in tick 0's settings.
#pragma once

#include "replay/replay_script.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace obscura {

struct ReplayInput {
    enum class Kind { KeyDown, KeyUp, MouseMotion } kind = Kind::KeyDown;
    std::string key;  // a key name, or mouse1..mouse3 for buttons
    int dx = 0, dy = 0;
};

struct ReplayTick {
    std::vector<ReplayInput> inputs;                          // before the step
    std::vector<const replay::Command*> settings;             // `set`, before the step
    std::vector<const replay::Command*> captures;             // after the step
    std::vector<const replay::Command*> hashes;               // after the step
};

class ReplayPlayer {
public:
    explicit ReplayPlayer(const replay::Script& script);

    // Everything due at `tick`; call once per tick, in order.
    ReplayTick take(std::int64_t tick);
    // The last tick to simulate (inclusive).
    std::int64_t lastTick() const { return lastTick_; }

private:
    const replay::Script& script_;
    std::size_t next_ = 0;
    std::int64_t lastTick_ = 0;
    std::multimap<std::int64_t, ReplayInput> pending_;  // tap releases
};

}  // namespace obscura
