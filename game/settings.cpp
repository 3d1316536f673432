// Settings table, parsing and validation. See settings.h.
#include "settings.h"

#include "map/input_file.h"
#include "map/map_compile.h"
#include "replay/replay_script.h"
#include "frame/frame_knobs.h"
#include "ssao/ssao_knobs.h"
#include "ssao/ssao_modes.h"
#include "ao_truth/truth_show.h"

#include <boost/program_options.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <unistd.h>

namespace po = boost::program_options;

namespace obscura {

namespace {

const char* const kActionNames[] = {"forward", "back", "left", "right", "jump", "crouch", "sprint", "fire",
                                    "reload", "throw", "cycle_ao", "ao_only_view", "cycle_view", "cycle_truth", "toggle_debug",
                                    "screenshot", "menu"};
static_assert(sizeof(kActionNames) / sizeof(kActionNames[0]) == static_cast<size_t>(Action::Count));

// The replay scripts' key names plus the mouse buttons.
std::vector<std::string> makeKeyNames() {
    std::vector<std::string> k = replay::keyNames();
    for (const char* n : {"mouse1", "mouse2", "mouse3"}) k.emplace_back(n);
    return k;
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

constexpr const char* kCommandLine = "command line";
// Paths from the command line or a config file (PATH_MAX is 4096 on Linux).
constexpr std::size_t kMaxPath = 4096;

[[noreturn]] void fail(const std::string& where, const std::string& key, const std::string& problem) {
    throw SettingsError(where + ": setting '" + key + "': " + problem);
}

// A value echoed in an error: escaped and cut to a readable length.
std::string q(const std::string& v) { return "'" + errorText(v) + "'"; }

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.15g", v);
    return buf;
}

bool parseBool(const std::string& v, const std::string& where, const std::string& key) {
    if (v == "1" || v == "true" || v == "yes" || v == "on") return true;
    if (v == "0" || v == "false" || v == "no" || v == "off") return false;
    fail(where, key, q(v) + " is not a boolean, expected true/false/1/0/yes/no/on/off");
}

// A finite decimal number, locale-free (std::from_chars: no hex, no "inf"/"nan", no blanks).
double parseNumber(const std::string& v, const std::string& where, const std::string& key) {
    double d = 0;
    const char* b = v.data() + (!v.empty() && v[0] == '+' ? 1 : 0);
    const auto r = std::from_chars(b, v.data() + v.size(), d);
    if (v.empty() || r.ec != std::errc() || r.ptr != v.data() + v.size() || !std::isfinite(d))
        fail(where, key, q(v) + " is not a number");
    return d;
}

// A number in [lo, hi]; outside it is an error (a knob typed wrong should be said so, not clamped).
double parseRanged(const std::string& v, double lo, double hi, const std::string& where, const std::string& key) {
    const double d = parseNumber(v, where, key);
    if (d < lo || d > hi) fail(where, key, q(v) + " is out of range, expected " + number(lo) + " to " + number(hi));
    return d;
}

long long parseInteger(const std::string& v, double lo, double hi, const std::string& where, const std::string& key) {
    const double d = parseRanged(v, lo, hi, where, key);
    if (d != std::floor(d)) fail(where, key, q(v) + " is not a whole number");
    return static_cast<long long>(d);
}

}  // namespace

std::string defaultConfigPath() {
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    const std::string base = xdg && *xdg ? xdg : std::string(home && *home ? home : "/tmp") + "/.config";
    return base + "/obscura/obscura.cfg";
}

std::string updateConfigText(const std::string& text, const std::vector<std::pair<std::string, std::string>>& values) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    for (const auto& [key, value] : values) {
        const std::string entry = key + " = " + value;
        long found = -1;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            std::string l = lines[i];
            const auto hash = l.find('#');
            if (hash != std::string::npos) l.resize(hash);
            const auto eq = l.find('=');
            if (eq != std::string::npos && trim(l.substr(0, eq)) == key) found = static_cast<long>(i);
        }
        if (found >= 0) lines[static_cast<std::size_t>(found)] = entry;
        else lines.push_back(entry);
    }
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

const char* actionName(Action a) { return kActionNames[static_cast<int>(a)]; }

std::optional<Action> actionFromName(const std::string& name) {
    for (int i = 0; i < static_cast<int>(Action::Count); ++i)
        if (name == kActionNames[i]) return static_cast<Action>(i);
    return std::nullopt;
}

const std::vector<std::string>& keyNames() {
    static const std::vector<std::string> names = makeKeyNames();
    return names;
}

bool isKeyName(const std::string& name) {
    for (const auto& k : keyNames())
        if (k == name) return true;
    return false;
}

Settings::Settings() {
    // Conventional FPS defaults. O is reserved for cycling the AO modes.
    bindings = {{Action::Forward, "w"},      {Action::Back, "s"},         {Action::Left, "a"},
                {Action::Right, "d"},        {Action::Jump, "space"},     {Action::Crouch, "lctrl"},
                {Action::Sprint, "lshift"},  {Action::Fire, "mouse1"},    {Action::Reload, "r"},
                {Action::Throw, "g"},        {Action::CycleAo, "o"},      {Action::AoOnlyView, "p"},   {Action::CycleView, "v"},
                {Action::CycleTruth, "t"},
                {Action::ToggleDebug, "f1"}, {Action::Screenshot, "f12"}, {Action::Menu, "escape"}};
}

// One entry per setting: its name, help, and how it is applied from a string.
struct Option {
    std::string name;
    std::string help;
    std::function<void(Settings&, const std::string& value, const std::string& where)> apply;
    bool isFlag = false;  // may be given without a value on the command line (means true)
};

// Settings that only make sense before the game starts; a replay's `set` may not change them.
const char* const kStartupOnly[] = {"start-pose", "level", "map-scale", "skill", "seed", "tick-rate", "width", "height", "fullscreen",
                                    "vsync", "headless", "ticks", "screenshot", "volume-dump", "light-dump", "irradiance-dump", "smoke-dump", "replay", "replay-draw", "capture-dir", "record",
                                    "timedemo", "config", "data-dir", "log", "debug-max-render-targets",
                                    "debug-unsupported-formats", "smoke-resolution", "truth-threads"};

struct SettingsParser::Impl {
    std::vector<Option> options;
    po::options_description desc{"Obscura options"};

    void add(Option o) { options.push_back(std::move(o)); }
    const Option* find(const std::string& name) const {
        for (const auto& o : options)
            if (o.name == name) return &o;
        return nullptr;
    }
};

SettingsParser::SettingsParser() : impl_(new Impl) {
    using S = Settings;
    using W = const std::string&;
    auto& I = *impl_;
    auto str = [](std::string S::*m) { return [m](S& s, W v, W) { s.*m = v; }; };
    auto flag = [](bool S::*m, const std::string& name) {
        return [m, name](S& s, W v, W where) { s.*m = parseBool(v, where, name); };
    };
    auto num = [](double S::*m, const std::string& name, double lo, double hi) {
        return [m, name, lo, hi](S& s, W v, W where) { s.*m = parseRanged(v, lo, hi, where, name); };
    };
    auto integer = [](int S::*m, const std::string& name, double lo, double hi) {
        return [m, name, lo, hi](S& s, W v, W where) { s.*m = static_cast<int>(parseInteger(v, lo, hi, where, name)); };
    };
    // A path the game writes: not empty, at most kMaxPath characters.
    auto path = [](std::string S::*m, const std::string& name) {
        return [m, name](S& s, W v, W where) {
            if (v.empty()) fail(where, name, "expected a path");
            if (v.size() > kMaxPath) fail(where, name, q(v) + " is longer than " + std::to_string(kMaxPath) + " characters");
            s.*m = v;
        };
    };
    // A knob's range comes from its table (core/knob.h), in its help too.
    auto rangeText = [](const Knob& k) {
        std::ostringstream os;
        os << "(" << k.min << " to " << k.max << ")";
        return os.str();
    };
    auto knob = [num](double S::*m, const Knob& k) { return num(m, k.name, k.min, k.max); };

    I.add({"level", "level .map file (default: media/levels/arena.map)", [](S& s, W v, W where) {
               if (v.empty()) fail(where, "level", "expected a .map file");
               if (v.size() > kMaxPath) fail(where, "level", q(v) + " is longer than " + std::to_string(kMaxPath) + " characters");
               // From a file: checked here, so the error names the config line. (The command line's
               // --level is opened by the loader, whose error names the file.)
               if (where != kCommandLine) {
                   std::error_code ec;
                   const auto st = std::filesystem::status(v, ec);
                   if (!std::filesystem::exists(st)) fail(where, "level", "map file " + q(v) + " not found");
                   if (!std::filesystem::is_regular_file(st)) fail(where, "level", q(v) + " is not a regular file, expected a .map file");
               }
               s.level = v;
           }});
    I.add({"map-scale", "map units per metre: 0 (worldspawn 'units_per_metre' or 32) or 1 to 1024", [](S& s, W v, W where) {
               const double d = parseNumber(v, where, "map-scale");
               if (d != 0 && !(d >= 1 && d <= 1024)) fail(where, "map-scale", q(v) + " is out of range, expected 0 (from the map) or 1 to 1024");
               s.mapScale = d;
           }});
    I.add({"skill", "Quake's skill: 0 easy, 1 normal, 2 hard, 3 nightmare (entities whose spawnflags exclude it are not spawned)",
           integer(&S::skill, "skill", map::kMinSkill, map::kMaxSkill)});
    I.add({"seed", "simulation RNG seed", [](S& s, W v, W where) {
               char* end = nullptr;
               errno = 0;
               const unsigned long long x = std::strtoull(v.c_str(), &end, 0);
               if (v.empty() || *end || errno == ERANGE || !std::isdigit(static_cast<unsigned char>(v[0])))
                   fail(where, "seed", q(v) + " is not an unsigned 64-bit integer");
               s.seed = x;
           }});
    I.add({"tick-rate", "simulation ticks per second (10 to 240)", num(&S::tickRate, "tick-rate", 10, 240)});
    // 16..8192: below 16 px nothing is visible; above 8192 exceeds GL3 texture limits.
    I.add({"width", "frame width in pixels (16 to 8192)", integer(&S::width, "width", 16, 8192)});
    I.add({"height", "frame height in pixels (16 to 8192)", integer(&S::height, "height", 16, 8192)});
    I.add({"fullscreen", "fullscreen window", flag(&S::fullscreen, "fullscreen"), true});
    I.add({"vsync", "wait for vertical sync", flag(&S::vsync, "vsync"), true});
    I.add({"fov", "horizontal field of view in degrees (40 to 140)", num(&S::fov, "fov", 40, 140)});
    I.add({"smoke-resolution", "smoke grid cells a side over its 16 m box: 64 (0.25 m cells) or 32 (0.5 m, an eighth of the cost)",
           [](S& s, W v, W where) {
               if (v != "32" && v != "64") fail(where, "smoke-resolution", q(v) + ", expected 32 or 64");
               s.smokeResolution = std::stoi(v);
           }});
    I.add({"decals", "decal cap (bullet holes, scorch marks), oldest recycled (1 to 1024)", integer(&S::decals, "decals", 1, 1024)});
    I.add({"debug-decals", "debug: N bullet holes scattered round the start at load, for engine_ext/decals' cost (0 to 1024)",
           integer(&S::debugDecals, "debug-decals", 0, 1024)});
    I.add({"debug-decals-cone", "debug: the debug-decals rays' half-angle about the start view, degrees (0 = all round, up to 90)",
           num(&S::debugDecalsCone, "debug-decals-cone", 0, 90)});
    I.add({"mouse-sensitivity", "mouse sensitivity, 0.01 to 20 (1 = 0.022 degrees per count)", num(&S::mouseSensitivity, "mouse-sensitivity", 0.01, 20)});
    I.add({"invert-mouse", "invert vertical mouse look", flag(&S::invertMouse, "invert-mouse"), true});
    I.add({"ssao", "ambient-occlusion mode: off, crytek, hemisphere, cone, horizon, heightfield, gtao, combined (O cycles them)", [](S& s, W v, W where) {
               if (!ssao::isMode(v)) {
                   std::string all;
                   for (const auto& m : ssao::modeNames()) all += (all.empty() ? "" : ", ") + m;
                   fail(where, "ssao", "unknown mode " + q(v) + ", expected one of " + all);
               }
               s.ssao = v;
           }});
    I.add({ssao::kRadius.name, "AO radius in metres " + rangeText(ssao::kRadius), knob(&S::ssaoRadius, ssao::kRadius)});
    I.add({ssao::kLargeRadius.name, "the combined AO mode's large-scale radius in metres " + rangeText(ssao::kLargeRadius),
           knob(&S::ssaoLargeRadius, ssao::kLargeRadius)});
    I.add({ssao::kIntensity.name, "AO strength " + rangeText(ssao::kIntensity), knob(&S::ssaoIntensity, ssao::kIntensity)});
    I.add({"ssao-resolution", "AO buffer resolution: full, half or quarter", [](S& s, W v, W where) {
               if (v != "half" && v != "full" && v != "quarter")
                   fail(where, "ssao-resolution", q(v) + ", expected full, half or quarter");
               s.ssaoResolution = v == "full" ? 1.0 : v == "half" ? 0.5 : 0.25;
           }});
    I.add({"ao-only", "show the AO term alone", flag(&S::aoOnly, "ao-only"), true});
    I.add({"master-volume", "master volume (0 to 1)", num(&S::masterVolume, "master-volume", 0, 1)});
    I.add({"effects-volume", "sound effects volume, 0 to 1 (times the master volume)", num(&S::effectsVolume, "effects-volume", 0, 1)});
    I.add({ssao::kSamples.name, "AO samples per pixel " + rangeText(ssao::kSamples),
           integer(&S::ssaoSamples, ssao::kSamples.name, ssao::kSamples.min, ssao::kSamples.max)});
    I.add({"view", "what the frame shows at the start: scene, ao, albedo, normal, depth, direct-light, hdr-light (V cycles)",
           str(&S::view)});
    I.add({"truth", "the AO truth key's picture over the frame: off, reference, mode, heatmap (T cycles; engine_ext/ao_truth)",
           [](S& s, W v, W where) {
               if (!ao_truth::showFromName(v)) fail(where, "truth", q(v) + ", expected off, reference, mode or heatmap");
               s.truth = std::string(v);
           }});
    I.add({"truth-rays", "the AO truth's rays per pixel (8 to 4096)", integer(&S::truthRays, "truth-rays", 8, 4096)});
    I.add({"truth-threads", "the AO truth's tracing threads (1 to 16)", integer(&S::truthThreads, "truth-threads", 1, 16)});
    I.add({"sign-mode", "back-lit signs' light: off, shafts, meshuggah (the seed's rays, for comparison; engine_ext/signs)", [](S& s, W v, W where) {
               if (v != "off" && v != "shafts" && v != "meshuggah") fail(where, "sign-mode", q(v) + ", expected off, shafts or meshuggah");
               s.signMode = std::string(v);
           }});
    I.add({signs::kHaze.name, "haze that shows the signs' shafts, per metre " + rangeText(signs::kHaze), knob(&S::signHaze, signs::kHaze)});
    I.add({frame::kExposure.name, "multiplies the light before the tone map " + rangeText(frame::kExposure),
           knob(&S::exposure, frame::kExposure)});
    I.add({"debug-unsupported-formats", "debug: pretend these render-target formats are missing (comma-separated OGRE "
                                        "names, e.g. PF_FLOAT32_GR; 3d: for volume textures)",
           [](S& s, W v, W) {
               s.debugUnsupportedFormats.clear();
               std::stringstream in(v);
               for (std::string f; std::getline(in, f, ',');)
                   if (!f.empty()) s.debugUnsupportedFormats.push_back(f);
           }});
    I.add({"debug-max-render-targets", "debug: pretend the GPU has at most N simultaneous render targets (0 = as it is) (0 to 8)",
           integer(&S::debugMaxRenderTargets, "debug-max-render-targets", 0, 8)});
    I.add({"headless", "no visible window: render to an offscreen texture (needs an X server, e.g. Xvfb)", flag(&S::headless, "headless"), true});
    I.add({"ticks", "run this many simulation ticks (0 to 1000000000), then exit (headless default 300)", [](S& s, W v, W where) {
               s.ticks = static_cast<long>(parseInteger(v, 0, 1e9, where, "ticks"));
           }});
    I.add({"screenshot", "write the last rendered frame to this PNG file", [](S& s, W v, W where) {
               std::string ext = std::filesystem::path(v).extension().string();
               std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
               if (ext != ".png") fail(where, "screenshot", q(v) + " does not end in .png (screenshots are PNG files)");
               if (v.size() > kMaxPath) fail(where, "screenshot", q(v) + " is longer than " + std::to_string(kMaxPath) + " characters");
               s.screenshot = v;
           }});
    I.add({"volume-dump", "write the last frame's volumetric light (half resolution, linear HDR) to this PFM file (tools/signref)",
           path(&S::volumeDump, "volume-dump")});
    I.add({"light-dump", "write the last frame's surface light before the volumes (linear HDR) to this PFM file (tools/signref)",
           path(&S::lightDump, "light-dump")});
    I.add({"irradiance-dump", "write the last frame's surface irradiance, direct + ambient before AO (linear HDR), to this PFM file (tools/lightref)",
           path(&S::irradianceDump, "irradiance-dump")});
    I.add({"smoke-dump", "write the smoke grids the last frame marched to this file (smoke/smoke_dump.h, tools/signref)",
           path(&S::smokeDump, "smoke-dump")});
    I.add({"replay", "play this replay script headless (implies --headless)", path(&S::replay, "replay")});
    I.add({"replay-draw", "a replay's frames drawn: every-frame, or captures (only those a capture reads and the last; "
                          "the replay tests' second run)", [](S& s, W v, W where) {
               if (v != "every-frame" && v != "captures") fail(where, "replay-draw", q(v) + ", expected every-frame or captures");
               s.replayDraw = v;
           }});
    I.add({"capture-dir", "folder for a replay's `capture <name>` frames (<name>.png)", path(&S::captureDir, "capture-dir")});
    I.add({"record", "record this session's inputs as a replay script to this file", path(&S::record, "record")});
    I.add({"timedemo", "play this replay script rendering every tick as fast as possible; print frame times", path(&S::timedemo, "timedemo")});
    I.add({"config", "config file of 'key = value' lines (same names as these options)", path(&S::configFile, "config")});
    I.add({"data-dir", "folder holding media/ and shaders/", path(&S::dataDir, "data-dir")});
    I.add({"log", "OGRE log file (default: obscura.log in the cache folder)", path(&S::logFile, "log")});
    I.add({"hud", "draw the crosshair and status text", flag(&S::hud, "hud"), true});
    // Poses and points share the replay format's checks (finite, x y z within +-300 km, yaw, pitch),
    // kept as written; checkInLevel() then holds them to the level's box.
    I.add({"start-pose", "start with the eye at 'x y z yaw pitch' (metres, degrees) instead of the player start",
           [](S& s, W v, W where) {
               const std::string problem = replay::checkPose(v);
               if (!problem.empty()) fail(where, "start-pose", problem);
               s.startPose = v;
           }});
    I.add({"smoke-at", "release a smoke grenade's cloud at 'x y z' (metres): at the start, or when a replay sets it",
           [](S& s, W v, W where) {
               const std::string problem = replay::checkPoint(v);
               if (!problem.empty()) fail(where, "smoke-at", problem);
               s.smokeAt = v;
           }});
    I.add({"debug-panel", "show the ImGui debug panel at start", flag(&S::showDebugPanel, "debug-panel"), true});
    for (int a = 0; a < static_cast<int>(Action::Count); ++a) {
        const auto action = static_cast<Action>(a);
        const std::string name = std::string("bind-") + actionName(action);
        I.add({name, std::string("key for '") + actionName(action) + "'", [action, name](S& s, W v, W where) {
                   if (!isKeyName(v)) fail(where, name, "unknown key " + q(v));
                   s.bindings[action] = v;
               }});
    }

    I.desc.add_options()("help,h", "print this help and exit");
    for (const auto& o : I.options) {
        if (o.isFlag)
            I.desc.add_options()(o.name.c_str(), po::value<std::string>()->implicit_value("true"), o.help.c_str());
        else
            I.desc.add_options()(o.name.c_str(), po::value<std::string>(), o.help.c_str());
    }
}

SettingsParser::~SettingsParser() { delete impl_; }

bool SettingsParser::isKnown(const std::string& key) const { return impl_->find(key) != nullptr; }

bool SettingsParser::isRuntime(const std::string& key) const {
    if (!isKnown(key)) return false;
    for (const char* k : kStartupOnly)
        if (key == k) return false;
    return true;
}

std::string SettingsParser::help() const {
    std::ostringstream os;
    os << "Usage: obscura [options]\n" << impl_->desc;
    return os.str();
}

void SettingsParser::apply(const std::string& key, const std::string& value, Settings& s, const std::string& where) const {
    const Option* o = impl_->find(key);
    if (!o) throw SettingsError(where + ": unknown setting " + q(key));
    // At run time (the menu, a replay's `set`) a key bound to another action swaps with it: the
    // bindings stay one key per action, as the files and command line must give them.
    std::optional<Action> action;
    std::string previous;
    if (key.rfind("bind-", 0) == 0 && (action = actionFromName(key.substr(5)))) previous = s.bindings[*action];
    o->apply(s, value, where);
    if (!action) return;
    for (auto& [other, bound] : s.bindings)
        if (other != *action && bound == s.bindings[*action]) bound = previous;
}

void SettingsParser::parseConfigText(const std::string& text, const std::string& fileName, Settings& out) const {
    std::istringstream in(text);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        line = trim(line);
        if (line.empty()) continue;
        const auto eq = line.find('=');
        const std::string where = fileName + ":" + std::to_string(n);
        if (eq == std::string::npos) throw SettingsError(where + ": expected 'key = value', got " + q(line));
        const std::string key = trim(line.substr(0, eq));
        if (key == "config") throw SettingsError(where + ": a config file cannot name another config file");
        const Option* o = impl_->find(key);
        if (!o) throw SettingsError(where + ": unknown setting " + q(key));
        o->apply(out, trim(line.substr(eq + 1)), where);
        out.sources[key] = where;
    }
}

void checkBindings(const Settings& s) {
    std::map<std::string, Action> owner;
    for (const auto& [action, key] : s.bindings) {
        const auto [it, fresh] = owner.emplace(key, action);
        if (fresh) continue;
        // Name the one a file or the command line set (a default never collides with a default).
        const auto source = [&](Action a) {
            const auto f = s.sources.find(std::string("bind-") + actionName(a));
            return f == s.sources.end() ? std::string() : f->second;
        };
        // The later of the two: the command line comes after the config file, lines in order.
        const auto order = [&](Action a) {
            const std::string w = source(a);
            if (w.empty()) return -1L;
            if (w == kCommandLine) return std::numeric_limits<long>::max();
            return std::strtol(w.c_str() + w.rfind(':') + 1, nullptr, 10);
        };
        Action culprit = action, other = it->second;
        if (order(culprit) < order(other)) std::swap(culprit, other);
        const std::string otherFrom = source(other).empty() ? "by default" : "at " + source(other);
        throw SettingsError(source(culprit) + ": setting 'bind-" + actionName(culprit) + "': key " + q(key) +
                            " is already bound to '" + actionName(other) + "' (" + otherFrom + "); one key per action");
    }
}

bool SettingsParser::parse(int argc, const char* const argv[], Settings& out) {
    po::variables_map vm;
    po::parsed_options parsed(&impl_->desc);
    try {
        parsed = po::command_line_parser(argc, argv).options(impl_->desc).run();
        po::store(parsed, vm);
    } catch (const po::error& e) {
        throw SettingsError(std::string(kCommandLine) + ": " + errorText(e.what(), 200) + " (see --help)");
    }
    if (vm.count("help")) {
        std::cout << help();
        return false;
    }
    for (const auto& opt : parsed.options)
        if (opt.position_key >= 0 || opt.string_key.empty())
            throw SettingsError(std::string(kCommandLine) + ": unexpected argument " +
                                q(opt.original_tokens.empty() ? std::string() : opt.original_tokens.front()) +
                                ": settings are given as --name value (see --help)");

    // The config file first, then the command line on top of it.
    std::string config;
    if (vm.count("config")) config = vm["config"].as<std::string>();
    if (!config.empty()) {
        std::string text, error;
        if (!readInputFile(config, kMaxConfigBytes, "config file", text, error)) throw SettingsError(error);
        parseConfigText(text, config, out);
    }
    for (const auto& opt : parsed.options) {
        if (opt.string_key == "help") continue;
        // A flag given bare (--headless) arrives with no value: its implicit value is true.
        const Option* o = impl_->find(opt.string_key);
        const std::string value = opt.value.empty() ? (o && o->isFlag ? "true" : "") : opt.value.front();
        if (!o) throw SettingsError(std::string(kCommandLine) + ": unknown setting " + q(opt.string_key));
        o->apply(out, value, kCommandLine);
        out.sources[opt.string_key] = kCommandLine;
    }
    checkBindings(out);
    return true;
}

std::vector<std::pair<std::string, std::string>> inputSettingValues(const Settings& s) {
    std::vector<std::pair<std::string, std::string>> v = {{"mouse-sensitivity", number(s.mouseSensitivity)},
                                                          {"invert-mouse", s.invertMouse ? "true" : "false"}};
    for (const auto& [action, key] : s.bindings) v.emplace_back(std::string("bind-") + actionName(action), key);
    return v;
}

namespace {
// Proves a file can be created in `dir` (a probe, removed again: access() says yes to root even
// where a read-only mount will refuse); `create` makes the folder first, as captures do.
std::string writableFolderProblem(const std::filesystem::path& dir, bool create) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path folder = dir.empty() ? fs::path(".") : dir;
    if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) return "is not a folder";
    if (create) fs::create_directories(folder, ec);
    if (ec) return "cannot be created (" + ec.message() + ")";
    if (!fs::is_directory(folder, ec)) return "does not exist";
    const fs::path probe = folder / (".obscura-write-test-" + std::to_string(::getpid()));
    const bool ok = static_cast<bool>(std::ofstream(probe.string()));
    fs::remove(probe, ec);
    return ok ? std::string() : "cannot be written";
}

}  // namespace

std::string sourceOf(const Settings& s, const std::string& key) {
    const auto it = s.sources.find(key);
    return it == s.sources.end() ? std::string(kCommandLine) : it->second;
}

void checkOutputsWritable(const Settings& s) {
    namespace fs = std::filesystem;
    const auto file = [&](const std::string& key, const std::string& path) {
        if (path.empty()) return;
        std::error_code ec;
        if (fs::is_directory(path, ec)) fail(sourceOf(s, key), key, q(path) + " is a folder, expected a file name");
        // Its folder is made, as the capture folder is (a new user's `--screenshot shots/a.png`).
        const fs::path parent = fs::path(path).parent_path();
        const std::string problem = writableFolderProblem(parent, true);
        if (!problem.empty())
            fail(sourceOf(s, key), key, "cannot write " + q(path) + ": its folder " + q(parent.empty() ? "." : parent.string()) + " " + problem);
    };
    file("screenshot", s.screenshot);
    file("volume-dump", s.volumeDump);
    file("light-dump", s.lightDump);
    file("irradiance-dump", s.irradianceDump);
    file("smoke-dump", s.smokeDump);
    file("record", s.record);
    if (!s.replay.empty()) {
        const std::string problem = writableFolderProblem(s.captureDir, true);
        if (!problem.empty()) fail(sourceOf(s, "capture-dir"), "capture-dir", "folder " + q(s.captureDir) + " " + problem);
    }
}

void checkInLevel(const Settings& s, const map::Level& level) {
    const auto check = [&](const std::string& key, const std::string& text, const std::string& where) {
        if (text.empty()) return;
        std::istringstream is(text);
        Vec3 p;
        is >> p.x >> p.y >> p.z;
        const map::Aabb box = map::placementRegion(level);
        if (!map::inside(box, p))
            fail(where, key,
                 "(" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + ") is outside " + errorText(level.sourcePath, 200) +
                     ": its brushes plus " + number(map::kPlacementMargin) + " m reach (" + number(box.min.x) + ", " + number(box.min.y) +
                     ", " + number(box.min.z) + ") to (" + number(box.max.x) + ", " + number(box.max.y) + ", " + number(box.max.z) + ")");
    };
    check("start-pose", s.startPose, sourceOf(s, "start-pose"));
    check("smoke-at", s.smokeAt, sourceOf(s, "smoke-at"));
}

}  // namespace obscura
