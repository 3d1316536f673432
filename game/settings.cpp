// Settings table, parsing and validation. See settings.h.
#include "settings.h"

#include "replay/replay_script.h"
#include "frame/frame_knobs.h"
#include "ssao/ssao_knobs.h"
#include "ssao/ssao_modes.h"

#include <boost/program_options.hpp>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>

namespace po = boost::program_options;

namespace obscura {

namespace {

const char* const kActionNames[] = {"forward", "back", "left", "right", "jump", "crouch", "sprint", "fire",
                                    "reload", "throw", "cycle_ao", "ao_only_view", "cycle_view", "toggle_debug",
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

[[noreturn]] void fail(const std::string& where, const std::string& key, const std::string& problem) {
    throw SettingsError(where + ": setting '" + key + "': " + problem);
}

bool parseBool(const std::string& v, const std::string& where, const std::string& key) {
    if (v == "1" || v == "true" || v == "yes" || v == "on") return true;
    if (v == "0" || v == "false" || v == "no" || v == "off") return false;
    fail(where, key, "'" + v + "' is not a boolean, expected true/false/1/0/yes/no/on/off");
}

double parseNumber(const std::string& v, const std::string& where, const std::string& key) {
    errno = 0;
    char* end = nullptr;
    const double d = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || errno == ERANGE || d != d)
        fail(where, key, "'" + v + "' is not a number");
    return d;
}

// Numbers out of range are clamped with a warning (a knob typed too large should still run).
double parseClamped(const std::string& v, double lo, double hi, const std::string& where, const std::string& key) {
    const double d = parseNumber(v, where, key);
    if (d < lo || d > hi) {
        const double c = d < lo ? lo : hi;
        std::cerr << "warning: " << where << ": setting '" << key << "' = " << v << " is outside [" << lo << ", "
                  << hi << "], clamped to " << c << "\n";
        return c;
    }
    return d;
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
const char* const kStartupOnly[] = {"start-pose", "level", "map-scale", "seed", "tick-rate", "width", "height", "fullscreen",
                                    "vsync", "headless", "ticks", "screenshot", "replay", "capture-dir", "record",
                                    "timedemo", "config", "data-dir", "log", "debug-max-render-targets",
                                    "debug-unsupported-formats"};

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
        return [m, name, lo, hi](S& s, W v, W where) { s.*m = parseClamped(v, lo, hi, where, name); };
    };
    auto integer = [](int S::*m, const std::string& name, double lo, double hi) {
        return [m, name, lo, hi](S& s, W v, W where) { s.*m = static_cast<int>(parseClamped(v, lo, hi, where, name)); };
    };
    // A knob's range comes from its table (core/knob.h).
    auto knob = [num](double S::*m, const Knob& k) { return num(m, k.name, k.min, k.max); };

    I.add({"level", "level .map file (default: media/levels/arena.map)", str(&S::level)});
    I.add({"map-scale", "map units per metre (0 = worldspawn 'units_per_metre' or 32)", num(&S::mapScale, "map-scale", 0, 1024)});
    I.add({"seed", "simulation RNG seed", [](S& s, W v, W where) {
               char* end = nullptr;
               errno = 0;
               const unsigned long long x = std::strtoull(v.c_str(), &end, 0);
               if (v.empty() || *end || errno == ERANGE || v[0] == '-') fail(where, "seed", "'" + v + "' is not an unsigned integer");
               s.seed = x;
           }});
    I.add({"tick-rate", "simulation ticks per second", num(&S::tickRate, "tick-rate", 10, 240)});
    // 16..8192: below 16 px nothing is visible; above 8192 exceeds GL3 texture limits.
    I.add({"width", "frame width in pixels", integer(&S::width, "width", 16, 8192)});
    I.add({"height", "frame height in pixels", integer(&S::height, "height", 16, 8192)});
    I.add({"fullscreen", "fullscreen window", flag(&S::fullscreen, "fullscreen"), true});
    I.add({"vsync", "wait for vertical sync", flag(&S::vsync, "vsync"), true});
    I.add({"fov", "horizontal field of view in degrees", num(&S::fov, "fov", 40, 140)});
    I.add({"decals", "decal cap (bullet holes, scorch marks), oldest recycled: 1..1024", integer(&S::decals, "decals", 1, 1024)});
    I.add({"debug-decals", "debug: N bullet holes scattered round the start at load (engine_ext/decals cost)",
           integer(&S::debugDecals, "debug-decals", 0, 1024)});
    I.add({"mouse-sensitivity", "mouse sensitivity (1 = 0.022 degrees per count)", num(&S::mouseSensitivity, "mouse-sensitivity", 0.01, 20)});
    I.add({"invert-mouse", "invert vertical mouse look", flag(&S::invertMouse, "invert-mouse"), true});
    I.add({"ssao", "ambient-occlusion mode: off, crytek, hemisphere, cone, horizon, heightfield (O cycles them)", [](S& s, W v, W where) {
               if (!ssao::isMode(v)) {
                   std::string all;
                   for (const auto& m : ssao::modeNames()) all += (all.empty() ? "" : ", ") + m;
                   fail(where, "ssao", "unknown mode '" + v + "', expected one of " + all);
               }
               s.ssao = v;
           }});
    I.add({ssao::kRadius.name, "AO radius in metres", knob(&S::ssaoRadius, ssao::kRadius)});
    I.add({ssao::kIntensity.name, "AO strength", knob(&S::ssaoIntensity, ssao::kIntensity)});
    I.add({"ssao-resolution", "AO buffer resolution: full, half or quarter", [](S& s, W v, W where) {
               if (v != "half" && v != "full" && v != "quarter")
                   fail(where, "ssao-resolution", "'" + v + "', expected full, half or quarter");
               s.ssaoResolution = v == "full" ? 1.0 : v == "half" ? 0.5 : 0.25;
           }});
    I.add({"ao-only", "show the AO term alone", flag(&S::aoOnly, "ao-only"), true});
    I.add({"master-volume", "master volume 0..1", num(&S::masterVolume, "master-volume", 0, 1)});
    I.add({"effects-volume", "sound effects volume 0..1 (times the master volume)", num(&S::effectsVolume, "effects-volume", 0, 1)});
    I.add({ssao::kSamples.name, "AO samples per pixel (1.." + std::to_string(static_cast<int>(ssao::kSamples.max)) + ")",
           integer(&S::ssaoSamples, ssao::kSamples.name, ssao::kSamples.min, ssao::kSamples.max)});
    I.add({"view", "what the frame shows at the start: scene, ao, albedo, normal, depth, direct-light, hdr-light (V cycles)",
           str(&S::view)});
    I.add({frame::kExposure.name, "multiplies the light before the tone map", knob(&S::exposure, frame::kExposure)});
    I.add({"debug-unsupported-formats", "debug: pretend these render-target formats are missing (comma-separated OGRE "
                                        "names, e.g. PF_FLOAT32_GR; 3d: for volume textures)",
           [](S& s, W v, W) {
               s.debugUnsupportedFormats.clear();
               std::stringstream in(v);
               for (std::string f; std::getline(in, f, ',');)
                   if (!f.empty()) s.debugUnsupportedFormats.push_back(f);
           }});
    I.add({"debug-max-render-targets", "debug: pretend the GPU has at most N simultaneous render targets (0 = as it is)",
           integer(&S::debugMaxRenderTargets, "debug-max-render-targets", 0, 8)});
    I.add({"headless", "no visible window: render to an offscreen texture (needs an X server, e.g. Xvfb)", flag(&S::headless, "headless"), true});
    I.add({"ticks", "run this many simulation ticks, then exit (headless default 300)", [](S& s, W v, W where) {
               s.ticks = static_cast<long>(parseClamped(v, 0, 1e9, where, "ticks"));
           }});
    I.add({"screenshot", "write the last rendered frame to this PNG file", str(&S::screenshot)});
    I.add({"replay", "play this replay script headless (implies --headless)", str(&S::replay)});
    I.add({"capture-dir", "folder for a replay's `capture <name>` frames (<name>.png)", str(&S::captureDir)});
    I.add({"record", "record this session's inputs as a replay script to this file", str(&S::record)});
    I.add({"timedemo", "play this replay script rendering every tick as fast as possible; print frame times", str(&S::timedemo)});
    I.add({"config", "config file of 'key = value' lines (same names as these options)", str(&S::configFile)});
    I.add({"data-dir", "folder holding media/ and shaders/", str(&S::dataDir)});
    I.add({"log", "OGRE log file (default: obscura.log in the cache folder)", str(&S::logFile)});
    I.add({"hud", "draw the crosshair and status text", flag(&S::hud, "hud"), true});
    // A text of `count` numbers, kept as written ("x y z yaw pitch").
    auto numbers = [](std::string S::*m, const std::string& name, int count, const std::string& expected) {
        return [m, name, count, expected](S& s, W v, W where) {
            std::istringstream is(v);
            double x;
            for (int i = 0; i < count; ++i)
                if (!(is >> x)) fail(where, name, "'" + v + "', expected '" + expected + "'");
            s.*m = v;
        };
    };
    I.add({"start-pose", "start with the eye at 'x y z yaw pitch' (metres, degrees) instead of the player start",
           numbers(&S::startPose, "start-pose", 5, "x y z yaw pitch")});
    I.add({"smoke-at", "release a smoke grenade's cloud at 'x y z' (metres): at the start, or when a replay sets it",
           numbers(&S::smokeAt, "smoke-at", 3, "x y z")});
    I.add({"debug-panel", "show the ImGui debug panel at start", flag(&S::showDebugPanel, "debug-panel"), true});
    for (int a = 0; a < static_cast<int>(Action::Count); ++a) {
        const auto action = static_cast<Action>(a);
        const std::string name = std::string("bind-") + actionName(action);
        I.add({name, std::string("key for '") + actionName(action) + "'", [action, name](S& s, W v, W where) {
                   if (!isKeyName(v)) fail(where, name, "unknown key '" + v + "'");
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
    if (!o) throw SettingsError(where + ": unknown setting '" + key + "'");
    o->apply(s, value, where);
}

bool SettingsParser::parse(int argc, const char* const argv[], Settings& out) {
    po::variables_map vm;
    po::parsed_options parsed(&impl_->desc);
    try {
        parsed = po::command_line_parser(argc, argv).options(impl_->desc).run();
    } catch (const po::error& e) {
        throw SettingsError(std::string("command line: ") + e.what() + " (see --help)");
    }
    po::store(parsed, vm);
    if (vm.count("help")) {
        std::cout << help();
        return false;
    }

    // The config file first, then the command line on top of it.
    std::string config;
    if (vm.count("config")) config = vm["config"].as<std::string>();
    if (!config.empty()) {
        std::ifstream in(config);
        if (!in) throw SettingsError(config + ": cannot open config file");
        std::string line;
        for (int n = 1; std::getline(in, line); ++n) {
            const auto hash = line.find('#');
            if (hash != std::string::npos) line.resize(hash);
            line = trim(line);
            if (line.empty()) continue;
            const auto eq = line.find('=');
            const std::string where = config + ":" + std::to_string(n);
            if (eq == std::string::npos) throw SettingsError(where + ": expected 'key = value', got '" + line + "'");
            const std::string key = trim(line.substr(0, eq));
            if (key == "config") throw SettingsError(where + ": a config file cannot name another config file");
            apply(key, trim(line.substr(eq + 1)), out, where);
        }
    }
    for (const auto& opt : parsed.options) {
        if (opt.string_key == "help") continue;
        // A flag given bare (--headless) arrives with no value: its implicit value is true.
        const Option* o = impl_->find(opt.string_key);
        const std::string value = opt.value.empty() ? (o && o->isFlag ? "true" : "") : opt.value.front();
        apply(opt.string_key, value, out, "command line");
    }
    return true;
}

}  // namespace obscura
