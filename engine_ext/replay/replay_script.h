// Replay scripts, format version 1: a versioned text format, one command a line.
//
//   # comment (also after a command)
//   obscura-replay 1            first non-comment line
//   level media/levels/arena.map
//   seed 12345
//   resolution 640 360
//   tickrate 60                 optional, default 60 (a decimal such as 59.94 is allowed)
//   start x y z yaw pitch       optional: the eye (metres) and view (degrees), as --start-pose
//   setting <name> <value...>   optional, repeatable: a run-time setting the session was recorded
//                               with (mouse-sensitivity, invert-mouse, bind-*), applied before tick 0
//   <tick> key <name> down|up|tap
//   <tick> mouse <dx> <dy>      relative motion in counts
//   <tick> button left|right|middle down|up|tap
//   <tick> capture <name>       [A-Za-z0-9_-]{1,243}, unique
//   <tick> set <setting> <value...>
//   <tick> hash [<expected 16-hex-digit hash>]
//   <tick> end                  optional; nothing may follow
//
// Ticks are non-negative and non-decreasing. Errors name file:line and what was expected; a token
// echoed in an error is cut to a readable length with raw bytes escaped.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace obscura::replay {

struct ScriptError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Limits: the script file (a 30-minute recording at 60 Hz with motion every tick is ~3 MB), a
// capture name (<name>.partial.png is written, and a file name holds 255 bytes), the level path,
// and the range of positions (a level can reach 262,144 map units at 1 unit per metre: 262 km;
// OGRE's shadow camera asserts near 1e10 m).
constexpr std::size_t kMaxScriptBytes = 16u << 20;
constexpr std::size_t kMaxCaptureName = 243;
constexpr std::size_t kMaxLevelPath = 4096;
constexpr double kMaxPosition = 300000;

struct Command {
    enum class Type { Key, Mouse, Button, Capture, Set, Hash, End };
    enum class Action { Down, Up, Tap };
    std::int64_t tick = 0;
    Type type = Type::End;
    std::string name;   // key, button (left/right/middle), capture or setting name
    std::string value;  // set: the value; hash: the expected hash (may be empty)
    Action action = Action::Down;
    int dx = 0, dy = 0;
    int line = 0;

    bool operator==(const Command& o) const {
        return tick == o.tick && type == o.type && name == o.name && value == o.value && action == o.action &&
               dx == o.dx && dy == o.dy;
    }
};

struct Script {
    std::string fileName;
    int version = 1;
    std::string level;
    std::uint64_t seed = 1;
    int width = 640, height = 360;
    double tickRate = 60;
    // Optional `start x y z yaw pitch`: the eye (metres) and view (degrees) instead of the level's
    // player start, as --start-pose takes them. Empty: the level's start.
    std::string start;
    int startLine = 0, levelLine = 0;  // where the `start` and `level` headers are (0: absent)
    // `setting` headers, as Set commands at tick 0 (applied before the first tick's own commands).
    std::vector<Command> settings;
    std::vector<Command> commands;

    // The last tick to simulate: the `end` command's, else the last command's.
    std::int64_t endTick() const;
    // The commands of one tick, in script order (commands are sorted by tick; binary search).
    std::vector<const Command*> commandsAt(std::int64_t tick) const;

    // Same header and commands; the file name and source line numbers are not compared.
    bool operator==(const Script& o) const {
        return version == o.version && level == o.level && seed == o.seed && width == o.width && height == o.height &&
               tickRate == o.tickRate && start == o.start && settings == o.settings && commands == o.commands;
    }
    bool operator!=(const Script& o) const { return !(*this == o); }
};

// Key names scripts accept (the same as the game's bindings).
const std::vector<std::string>& keyNames();
// Script mouse buttons (left/right/middle) <-> the bindings' key names (mouse1/mouse2/mouse3).
std::string buttonKeyName(const std::string& button);
std::string buttonFromKeyName(const std::string& key);

// A pose "x y z yaw pitch" (the `start` header, --start-pose): exactly five finite numbers, x y z
// within +-kMaxPosition metres, yaw -360..360 and pitch -90..90 degrees. "" if valid, else the problem.
std::string checkPose(const std::string& text);
// A point "x y z" (--smoke-at): three finite numbers within +-kMaxPosition. "" or the problem.
std::string checkPoint(const std::string& text);

// The script's level as a path to open: relative paths beside the script first, then in `dataDir`.
// Throws ScriptError naming the script's `level` line if it is missing, a directory or a device.
std::string resolveLevel(const Script& script, const std::string& dataDir);

Script parseScript(std::string_view text, const std::string& fileName,
                   const std::function<bool(const std::string&)>& isKnownSetting = {});
// Reads at most kMaxScriptBytes; a directory or device is refused by name.
Script loadScript(const std::string& path, const std::function<bool(const std::string&)>& isKnownSetting = {});
// Writes a script back in canonical form (used by --record): parseScript(formatScript(s)) == s for
// every script the parser or the Recorder produces.
std::string formatScript(const Script& s);

}  // namespace obscura::replay
