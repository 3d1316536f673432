// See replay_recorder.h.
#include "replay/replay_recorder.h"

#include <algorithm>

namespace obscura::replay {

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
        c.name = buttonFromKeyName(key);
    } else {
        c.type = Command::Type::Key;
        c.name = key;
    }
    script_.commands.push_back(c);
}

void Recorder::keyDown(std::int64_t tick, const std::string& k) { key(tick, k, Command::Action::Down); }
void Recorder::keyUp(std::int64_t tick, const std::string& k) { key(tick, k, Command::Action::Up); }

void Recorder::button(std::int64_t tick, const std::string& button, bool down) {
    if (button != "left" && button != "right" && button != "middle")
        throw ScriptError("Recorder: unknown button '" + button + "', expected left, right or middle");
    key(tick, buttonKeyName(button), down ? Command::Action::Down : Command::Action::Up);
}

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

void Recorder::add(std::int64_t tick, Command::Type type, const std::string& name, const std::string& value) {
    Command c;
    c.tick = tick;
    c.type = type;
    c.name = name;
    c.value = value;
    script_.commands.push_back(c);
}

void Recorder::setting(const std::string& name, const std::string& value) {
    Command c;
    c.type = Command::Type::Set;
    c.name = name;
    c.value = value;
    script_.settings.push_back(c);
}

void Recorder::set(std::int64_t tick, const std::string& name, const std::string& value) { add(tick, Command::Type::Set, name, value); }

void Recorder::capture(std::int64_t tick, const std::string& name) { add(tick, Command::Type::Capture, name, {}); }
void Recorder::hash(std::int64_t tick, const std::string& expected) { add(tick, Command::Type::Hash, {}, expected); }
void Recorder::end(std::int64_t tick) { add(tick, Command::Type::End, {}, {}); }

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
