// See replay_script.h.
#include "replay/replay_script.h"

#include "map/input_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <filesystem>
#include <map>
#include <sstream>

namespace obscura::replay {

namespace {
constexpr int kVersion = 1;

std::vector<std::string> split(const std::string& line) {
    std::istringstream is(line);
    std::vector<std::string> out;
    std::string w;
    while (is >> w) out.push_back(w);
    return out;
}

// The shortest decimal text that reads back as exactly `v` (60 -> "60", 59.94 -> "59.94").
std::string shortest(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}
// Tick rates the fixed-step simulation is meant for: below 10 Hz movement and collision get
// coarse, above 240 Hz a replay costs more steps than frames are worth on the test machines.
constexpr double kMinTickRate = 10, kMaxTickRate = 240;

// A token echoed in an error: escaped and cut (a 10 MB token must not give a 10 MB line).
std::string q(const std::string& token) { return "'" + errorText(token) + "'"; }

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.15g", v);
    return buf;
}

struct NumberSpec {
    const char* name;
    double lo, hi;
};

// Exactly specs.size() blank-separated finite numbers, each in its range; "" or the problem.
std::string checkNumbers(const std::string& text, std::initializer_list<NumberSpec> specs, const char* usage) {
    const std::vector<std::string> w = split(text);
    if (w.size() != specs.size())
        return std::to_string(w.size()) + " numbers in " + q(text) + ", expected '" + usage + "'";
    std::size_t i = 0;
    for (const NumberSpec& spec : specs) {
        const std::string& t = w[i++];
        double v = 0;
        const char* b = t.data() + (t[0] == '+' ? 1 : 0);
        const auto r = std::from_chars(b, t.data() + t.size(), v);
        if (r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v))
            return q(t) + " (" + spec.name + ") is not a number, expected '" + usage + "'";
        if (v < spec.lo || v > spec.hi)
            return q(t) + " (" + spec.name + ") is out of range, expected " + number(spec.lo) + " to " + number(spec.hi);
    }
    return {};
}

class Parser {
public:
    Parser(const std::string& file, const std::function<bool(const std::string&)>& known) : file_(file), known_(known) {}

    [[noreturn]] void fail(const std::string& problem) const {
        throw ScriptError(file_ + ":" + std::to_string(line_) + ": " + problem);
    }

    std::int64_t integer(const std::string& s, const char* what, std::int64_t lo, std::int64_t hi) const {
        errno = 0;
        char* end = nullptr;
        const long long v = std::strtoll(s.c_str(), &end, 10);
        if (s.empty() || *end || errno == ERANGE) fail(q(s) + " is not an integer, expected " + what);
        if (v < lo || v > hi) fail(std::string(what) + " " + errorText(s) + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return v;
    }

    void arity(const std::vector<std::string>& w, std::size_t n, const char* usage) const {
        if (w.size() != n) fail(std::string(w.size() < n ? "missing arguments" : "extra arguments") + ", expected '" + usage + "'");
    }

    Command::Action action(const std::string& s) const {
        if (s == "down") return Command::Action::Down;
        if (s == "up") return Command::Action::Up;
        if (s == "tap") return Command::Action::Tap;
        fail("unknown action " + q(s) + ", expected down, up or tap");
    }

    void header(Script& s, const std::vector<std::string>& w) {
        if (w[0] == "level") {
            if (w.size() < 2) fail("missing path, expected 'level <path>'");
            std::string path = w[1];
            for (std::size_t i = 2; i < w.size(); ++i) path += " " + w[i];
            if (path.size() > kMaxLevelPath) fail("level path " + q(path) + " is longer than " + std::to_string(kMaxLevelPath) + " characters");
            s.level = path;
            s.levelLine = line_;
        } else if (w[0] == "seed") {
            arity(w, 2, "seed <unsigned integer>");
            errno = 0;
            char* end = nullptr;
            // Base 10 only: a leading zero must not turn "010" into octal 8.
            const unsigned long long v = std::strtoull(w[1].c_str(), &end, 10);
            if (*end || errno == ERANGE || !std::isdigit(static_cast<unsigned char>(w[1][0])))
                fail(q(w[1]) + " is not an unsigned 64-bit integer, expected a seed");
            s.seed = v;
        } else if (w[0] == "resolution") {
            arity(w, 3, "resolution <width> <height>");
            s.width = static_cast<int>(integer(w[1], "a width", 16, 8192));
            s.height = static_cast<int>(integer(w[2], "a height", 16, 8192));
        } else if (w[0] == "tickrate") {
            arity(w, 2, "tickrate <ticks per second>");
            double v = 0;
            const auto r = std::from_chars(w[1].data(), w[1].data() + w[1].size(), v);
            if (r.ec != std::errc() || r.ptr != w[1].data() + w[1].size() || !std::isdigit(static_cast<unsigned char>(w[1][0])) ||
                !std::isfinite(v))
                fail(q(w[1]) + " is not a number, expected ticks per second");
            if (v < kMinTickRate || v > kMaxTickRate)
                fail("tick rate " + errorText(w[1]) + " is out of range, expected " + shortest(kMinTickRate) + " to " + shortest(kMaxTickRate));
            s.tickRate = v;
        } else if (w[0] == "start") {
            arity(w, 6, "start <x> <y> <z> <yaw> <pitch>");
            std::string pose;
            for (std::size_t i = 1; i < 6; ++i) pose += (i > 1 ? " " : "") + w[i];
            const std::string problem = checkPose(pose);
            if (!problem.empty()) fail("start " + problem);
            s.start = pose;
            s.startLine = line_;
        } else if (w[0] == "setting") {
            // A setting the session was recorded with (mouse sensitivity, invert, bindings):
            // applied before the first tick, as a `0 set` would be.
            if (w.size() < 3) fail("missing arguments, expected 'setting <name> <value>'");
            if (known_ && !known_(w[1]))
                fail("unknown setting " + q(w[1]) + ", expected a setting `obscura --help` lists that can change at run time");
            Command c;
            c.type = Command::Type::Set;
            c.line = line_;
            c.name = w[1];
            c.value = w[2];
            for (std::size_t i = 3; i < w.size(); ++i) c.value += " " + w[i];
            s.settings.push_back(std::move(c));
        } else {
            fail("unknown header " + q(w[0]) + ", expected level, seed, resolution, tickrate, start, setting or '<tick> <command>'");
        }
    }

    Command command(const std::vector<std::string>& w, std::int64_t tick) {
        Command c;
        c.tick = tick;
        c.line = line_;
        const std::string& cmd = w[1];
        if (cmd == "key") {
            arity(w, 4, "<tick> key <name> down|up|tap");
            const auto& k = keyNames();
            if (std::find(k.begin(), k.end(), w[2]) == k.end()) fail("unknown key " + q(w[2]) + ", expected a key name such as w, space, lshift, f1");
            c.type = Command::Type::Key;
            c.name = w[2];
            c.action = action(w[3]);
        } else if (cmd == "mouse") {
            arity(w, 4, "<tick> mouse <dx> <dy>");
            c.type = Command::Type::Mouse;
            c.dx = static_cast<int>(integer(w[2], "a mouse dx", -100000, 100000));
            c.dy = static_cast<int>(integer(w[3], "a mouse dy", -100000, 100000));
        } else if (cmd == "button") {
            arity(w, 4, "<tick> button left|right|middle down|up|tap");
            if (w[2] != "left" && w[2] != "right" && w[2] != "middle") fail("unknown button " + q(w[2]) + ", expected left, right or middle");
            c.type = Command::Type::Button;
            c.name = w[2];
            c.action = action(w[3]);
        } else if (cmd == "capture") {
            arity(w, 3, "<tick> capture <name>");
            const bool ok = std::all_of(w[2].begin(), w[2].end(), [](char ch) {
                return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-';
            });
            if (!ok) fail("bad capture name " + q(w[2]) + ", expected letters, digits, '_' and '-'");
            if (w[2].size() > kMaxCaptureName)
                fail("capture name " + q(w[2]) + " is " + std::to_string(w[2].size()) + " characters, expected at most " +
                     std::to_string(kMaxCaptureName) + " (<name>.partial.png must fit a 255-byte file name)");
            const auto [it, fresh] = captures_.emplace(w[2], line_);
            if (!fresh) fail("duplicate capture name " + q(w[2]) + " (first on line " + std::to_string(it->second) + "), expected a unique name");
            c.type = Command::Type::Capture;
            c.name = w[2];
        } else if (cmd == "set") {
            if (w.size() < 4) fail("missing arguments, expected '<tick> set <setting> <value>'");
            if (known_ && !known_(w[2])) fail("unknown setting " + q(w[2]) + ", expected a setting `obscura --help` lists that can change at run time");
            c.type = Command::Type::Set;
            c.name = w[2];
            c.value = w[3];
            for (std::size_t i = 4; i < w.size(); ++i) c.value += " " + w[i];
        } else if (cmd == "hash") {
            if (w.size() > 3) fail("extra arguments, expected '<tick> hash [<expected hash>]'");
            c.type = Command::Type::Hash;
            if (w.size() == 3) {
                const bool hex = w[2].size() == 16 && std::all_of(w[2].begin(), w[2].end(), [](char ch) {
                                     return std::isdigit(static_cast<unsigned char>(ch)) || (ch >= 'a' && ch <= 'f');
                                 });
                if (!hex) fail("bad expected hash " + q(w[2]) + ", expected 16 lower-case hex digits");
                c.value = w[2];
            }
        } else if (cmd == "end") {
            arity(w, 2, "<tick> end");
            c.type = Command::Type::End;
        } else {
            fail("unknown command " + q(cmd) + ", expected one of key, mouse, button, capture, set, hash, end");
        }
        return c;
    }

    Script parse(std::string_view text) {
        Script s;
        s.fileName = file_;
        std::istringstream in{std::string(text)};
        std::string raw;
        bool sawVersion = false, ended = false;
        std::int64_t lastTick = 0;
        int lastTickLine = 0;
        while (std::getline(in, raw)) {
            ++line_;
            const auto hash = raw.find('#');
            if (hash != std::string::npos) raw.resize(hash);
            const auto w = split(raw);
            if (w.empty()) continue;
            if (!sawVersion) {
                if (w[0] != "obscura-replay")
                    fail("expected the header 'obscura-replay " + std::to_string(kVersion) + "' first, found " + q(w[0]));
                arity(w, 2, "obscura-replay <version>");
                s.version = static_cast<int>(integer(w[1], "a version", 0, 1000000));
                if (s.version != kVersion) fail("unsupported version " + errorText(w[1]) + ", expected " + std::to_string(kVersion));
                sawVersion = true;
                continue;
            }
            if (ended) {
                std::string text = w[0];
                for (std::size_t i = 1; i < w.size(); ++i) text += " " + w[i];
                fail(q(text) + " after 'end', expected nothing");
            }
            const bool isTick = std::isdigit(static_cast<unsigned char>(w[0][0])) || w[0][0] == '-';
            if (!isTick) {
                if (!s.commands.empty()) fail("header " + q(w[0]) + " after the first command, expected '<tick> <command>'");
                header(s, w);
                continue;
            }
            if (s.level.empty()) fail("the header has no 'level <path>' line before the first command");
            if (w.size() < 2) fail("missing command after tick, expected '<tick> <command>'");
            const std::int64_t tick = integer(w[0], "a tick", 0, 1000000000);
            if (tick < lastTick) fail("tick " + errorText(w[0]) + " is before tick " + std::to_string(lastTick) + " of line " + std::to_string(lastTickLine));
            lastTick = tick;
            lastTickLine = line_;
            s.commands.push_back(command(w, tick));
            ended = s.commands.back().type == Command::Type::End;
        }
        if (!sawVersion) {
            line_ = std::max(line_, 1);
            fail("empty script, expected the header 'obscura-replay " + std::to_string(kVersion) + "'");
        }
        if (s.level.empty()) fail("the header has no 'level <path>' line");
        return s;
    }

private:
    const std::string& file_;
    const std::function<bool(const std::string&)>& known_;
    int line_ = 0;
    std::map<std::string, int> captures_;  // capture name -> line it was first used on
};

const char* actionName(Command::Action a) {
    return a == Command::Action::Down ? "down" : a == Command::Action::Up ? "up" : "tap";
}
}  // namespace

std::int64_t Script::endTick() const { return commands.empty() ? 0 : commands.back().tick; }

std::vector<const Command*> Script::commandsAt(std::int64_t tick) const {
    const auto lo = std::lower_bound(commands.begin(), commands.end(), tick,
                                     [](const Command& c, std::int64_t t) { return c.tick < t; });
    std::vector<const Command*> out;
    for (auto it = lo; it != commands.end() && it->tick == tick; ++it) out.push_back(&*it);
    return out;
}

const std::vector<std::string>& keyNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> k;
        for (char c = 'a'; c <= 'z'; ++c) k.emplace_back(1, c);
        for (char c = '0'; c <= '9'; ++c) k.emplace_back(1, c);
        for (const char* n : {"space", "return", "escape", "tab", "backspace", "lshift", "rshift", "lctrl", "rctrl",
                              "lalt", "ralt", "up", "down", "left", "right", "minus", "equals", "comma", "period",
                              "slash", "grave"})
            k.emplace_back(n);
        for (int i = 1; i <= 12; ++i) k.push_back("f" + std::to_string(i));
        return k;
    }();
    return names;
}

std::string buttonKeyName(const std::string& button) {
    return button == "left" ? "mouse1" : button == "right" ? "mouse2" : "mouse3";
}

std::string buttonFromKeyName(const std::string& key) {
    return key == "mouse1" ? "left" : key == "mouse2" ? "right" : "middle";
}

Script parseScript(std::string_view text, const std::string& fileName, const std::function<bool(const std::string&)>& isKnownSetting) {
    return Parser(fileName, isKnownSetting).parse(text);
}

Script loadScript(const std::string& path, const std::function<bool(const std::string&)>& isKnownSetting) {
    std::string text, error;
    if (!readInputFile(path, kMaxScriptBytes, "replay script", text, error)) throw ScriptError(error);
    return parseScript(text, path, isKnownSetting);
}

std::string checkPose(const std::string& text) {
    return checkNumbers(text,
                        {{"x", -kMaxPosition, kMaxPosition}, {"y", -kMaxPosition, kMaxPosition}, {"z", -kMaxPosition, kMaxPosition},
                         {"yaw", -360, 360}, {"pitch", -90, 90}},
                        "x y z yaw pitch");
}

std::string checkPoint(const std::string& text) {
    return checkNumbers(text, {{"x", -kMaxPosition, kMaxPosition}, {"y", -kMaxPosition, kMaxPosition}, {"z", -kMaxPosition, kMaxPosition}},
                        "x y z");
}

std::string resolveLevel(const Script& script, const std::string& dataDir) {
    namespace fs = std::filesystem;
    fs::path level = script.level;
    std::string looked;
    if (level.is_relative()) {
        const fs::path besideScript = fs::path(script.fileName).parent_path() / level;
        looked = " (looked beside the script and in " + errorText(dataDir, 200) + ")";
        level = fs::exists(besideScript) ? besideScript : fs::path(dataDir) / level;
    }
    const std::string where = script.fileName + ":" + std::to_string(script.levelLine) + ": level " + q(script.level);
    std::error_code ec;
    const fs::file_status st = fs::status(level, ec);
    if (ec || !fs::exists(st)) throw ScriptError(where + " not found" + looked);
    if (fs::is_directory(st)) throw ScriptError(where + " is a directory, expected a map file");
    if (!fs::is_regular_file(st)) throw ScriptError(where + " is not a regular file, expected a map file");
    return level.string();
}

std::string formatScript(const Script& s) {
    std::ostringstream o;
    o << "obscura-replay " << kVersion << "\n";
    o << "level " << s.level << "\nseed " << s.seed << "\nresolution " << s.width << " " << s.height << "\n";
    o << "tickrate " << shortest(s.tickRate) << "\n";
    if (!s.start.empty()) o << "start " << s.start << "\n";
    for (const auto& c : s.settings) o << "setting " << c.name << " " << c.value << "\n";
    for (const auto& c : s.commands) {
        o << c.tick << " ";
        switch (c.type) {
            case Command::Type::Key: o << "key " << c.name << " " << actionName(c.action); break;
            case Command::Type::Mouse: o << "mouse " << c.dx << " " << c.dy; break;
            case Command::Type::Button: o << "button " << c.name << " " << actionName(c.action); break;
            case Command::Type::Capture: o << "capture " << c.name; break;
            case Command::Type::Set: o << "set " << c.name << " " << c.value; break;
            case Command::Type::Hash: o << "hash" << (c.value.empty() ? "" : " " + c.value); break;
            case Command::Type::End: o << "end"; break;
        }
        o << "\n";
    }
    return o.str();
}

}  // namespace obscura::replay
