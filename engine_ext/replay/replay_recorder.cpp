// See replay_recorder.h.
#include "replay/replay_recorder.h"

#include <algorithm>

namespace obscura::replay {

namespace {
std::string buttonName(const std::string& key) {
    if (key == "mouse1") return "left";
    if (key == "mouse2") return "right";
    return "middle";
}
}  // namespace

Recorder::Recorder(std::string level, std::uint64_t seed, int width, int height, double tickRate) {
    script_.level = std::move(level);
    script_.seed = seed;
    script_.width = width;
    script_.height = height;
    script_.tickRate = tickRate;
}

void Recorder::key(std::int64_t tick, const std::string& key, Command::Action action) {
    Command c;
    c.tick = tick;
    c.action = action;
    if (key.rfind("mouse", 0) == 0) {
        c.type = Command::Type::Button;
        c.name = buttonName(key);
    } else {
        c.type = Command::Type::Key;
        c.name = key;
    }
    script_.commands.push_back(c);
}

void Recorder::keyDown(std::int64_t tick, const std::string& k) { key(tick, k, Command::Action::Down); }
void Recorder::keyUp(std::int64_t tick, const std::string& k) { key(tick, k, Command::Action::Up); }

void Recorder::mouse(std::int64_t tick, int dx, int dy) {
    if (mouseIndex_ >= 0 && script_.commands[static_cast<std::size_t>(mouseIndex_)].tick == tick) {
        auto& c = script_.commands[static_cast<std::size_t>(mouseIndex_)];
        c.dx += dx;
        c.dy += dy;
        return;
    }
    Command c;
    c.tick = tick;
    c.type = Command::Type::Mouse;
    c.dx = dx;
    c.dy = dy;
    mouseIndex_ = static_cast<int>(script_.commands.size());
    script_.commands.push_back(c);
}

void Recorder::capture(std::int64_t tick, const std::string& name) {
    Command c;
    c.tick = tick;
    c.type = Command::Type::Capture;
    c.name = name;
    script_.commands.push_back(c);
}

void Recorder::hash(std::int64_t tick, const std::string& expected) {
    Command c;
    c.tick = tick;
    c.type = Command::Type::Hash;
    c.value = expected;
    script_.commands.push_back(c);
}

void Recorder::end(std::int64_t tick) {
    Command c;
    c.tick = tick;
    c.type = Command::Type::End;
    script_.commands.push_back(c);
}

Script Recorder::script() const {
    Script s = script_;
    // Stable: commands of one tick keep the order they happened in; `end` goes last.
    std::stable_sort(s.commands.begin(), s.commands.end(), [](const Command& a, const Command& b) {
        if (a.tick != b.tick) return a.tick < b.tick;
        return (a.type != Command::Type::End) && (b.type == Command::Type::End);
    });
    return s;
}

}  // namespace obscura::replay
