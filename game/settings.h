// Obscura's settings: one table of options shared by the command line (Boost.ProgramOptions),
// the config file (`key = value` lines) and the replay `set` command, so every setting has one
// name, one parser and one range check everywhere.
#pragma once

#include "frame/frame_knobs.h"
#include "map/level.h"
#include "map/spawnflags.h"
#include "ssao/ssao_knobs.h"
#include "signs/sign_knobs.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace obscura {

// Thrown for bad input; the message names the source (file:line or "command line") and the problem.
struct SettingsError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Game actions a key or mouse button can be bound to. O is reserved for cycle_ao.
enum class Action {
    Forward, Back, Left, Right, Jump, Crouch, Sprint, Fire, Reload, Throw,
    CycleAo, AoOnlyView, CycleView, CycleTruth, ToggleDebug, Screenshot, Menu, Count
};
const char* actionName(Action a);
std::optional<Action> actionFromName(const std::string& name);

struct Settings {
    // Level and simulation
    std::string level;           // .map path; empty = the default level
    double mapScale = 0;         // map units per metre; 0 = from the map (worldspawn) or 32
    int skill = map::kDefaultSkill;  // Quake's skill 0..3: entities flagged out of it are not spawned (map/spawnflags.h)
    std::uint64_t seed = 1;
    double tickRate = 60;
    // Display
    int width = 1280, height = 720;
    bool fullscreen = false;
    bool vsync = true;
    double fov = 90;             // horizontal degrees
    // Smoke grid cells a side over the same 16 m box: 64 (0.25 m cells) or 32 (0.5 m: an eighth of
    // the solver's cost, for slow machines and long soaks; coarser clouds). engine_ext/smoke
    int smokeResolution = 64;
    int decals = 256;            // decal cap, oldest recycled (Quake III 256, GoldSrc mp_decals 300); engine_ext/decals
    int debugDecals = 0;         // debug: this many bullet holes scattered round the start (the decal cost bench)
    double debugDecalsCone = 0;  // debug: their rays' half-angle about the start view (degrees); 0: all round
    // Input
    double mouseSensitivity = 1.0;  // multiplies 0.022 deg per count (Quake's m_yaw)
    bool invertMouse = false;
    std::map<Action, std::string> bindings;  // action -> key name (see keyNames())
    // Audio (engine_ext/audio): effects = master x effects; UI sounds use master alone
    double masterVolume = 0.8;   // 0..1: leaves headroom for several shots at once
    double effectsVolume = 1.0;
    // Ambient occlusion (engine_ext/ssao). The default is picked by the error/cost table in
    // engine_ext/ssao/README.md: lowest error of the modes at a third of the cost of a full-resolution
    // 32-sample hemisphere.
    std::string ssao = "combined";
    double ssaoRadius = ssao::kRadius.value;  // defaults and reasons: engine_ext/ssao/ssao_knobs.h
    double ssaoLargeRadius = ssao::kLargeRadius.value;  // the combined mode's large scale
    double ssaoIntensity = ssao::kIntensity.value;
    int ssaoSamples = static_cast<int>(ssao::kSamples.value);
    // AO buffers at a quarter of the width and height: with the depth-aware blur and upsampling it
    // looked the same as half at 720p, measured lower error than full-resolution 32 samples, and
    // cut the AO passes' cost to a quarter (engine_ext/ssao/README.md).
    double ssaoResolution = 0.25;  // of the frame's width and height: 1, 0.5 or 0.25
    int debugMaxRenderTargets = 0;  // debug: pretend the GPU has at most this many MRTs (0 = real)
    std::vector<std::string> debugUnsupportedFormats;  // debug: render-target formats pretended missing
    double exposure = frame::kExposure.value;  // engine_ext/frame/frame_knobs.h
    // The back-lit signs (engine_ext/signs): how their light is drawn (off, shafts: the shafts and
    // the lettered light on surfaces; meshuggah: the seed's rays instead of the shafts) and the haze that shows the shafts.
    std::string signMode = "shafts";
    double signHaze = signs::kHaze.value;
    std::string view = "scene";  // what the frame shows at the start (V cycles): scene, ao, albedo, ...
    bool aoOnly = false;         // show the AO term alone (P toggles it)
    // The truth key (engine_ext/ao_truth, T cycles): what is shown over the frame (off, reference,
    // mode, heatmap), the reference's rays per pixel (256: ssao/README's table's, noise up to
    // +-0.03) and the tracer's threads (1: this machine's second core draws the frame, llvmpipe).
    std::string truth = "off";
    int truthRays = 256;
    int truthThreads = 1;
    // Headless runs
    bool headless = false;
    long ticks = 0;              // 0 = run until quit (windowed) / 300 (headless)
    std::string screenshot;      // PNG written from the last frame
    // tools/signref's inputs, written from the last frame (core/pfm.h, smoke/smoke_dump.h): the
    // volumetric pass's in-scattered light, the surfaces' light, the smoke grids it marched.
    std::string volumeDump, lightDump, irradianceDump, smokeDump;
    // Replays (engine_ext/replay): play a script, record one, or benchmark one
    std::string replay;          // script to play (implies headless)
    std::string replayDraw = "every-frame";  // or "captures": only the frames a capture reads (and the last)
    std::string captureDir = "."; // where `capture <name>` writes <name>.png
    std::string record;          // write a replay of this session here
    std::string timedemo;        // play this script as fast as possible and print frame-time statistics
    // Paths
    std::string configFile;
    std::string dataDir;         // holds media/ and shaders/
    std::string logFile;
    bool showDebugPanel = false;
    bool hud = true;             // crosshair and status text (off for AO comparisons)
    // Start the player's eye here instead of the level's player start: x y z (metres, world),
    // yaw pitch (degrees, the game's convention). Empty: the level's start.
    std::string startPose;
    // Release a smoke grenade's cloud at "x y z" (metres) when the level starts, or at the tick a
    // replay `set`s it (tests, screenshots).
    std::string smokeAt;
    // Where each setting given by a file or the command line came from ("file:line", "command
    // line"), for errors found after parsing (duplicate bindings, a pose outside the level).
    std::map<std::string, std::string> sources;

    Settings();  // fills default bindings
};

// Valid key names (the same names replays use): a-z, 0-9, space, lshift, mouse1...
const std::vector<std::string>& keyNames();
bool isKeyName(const std::string& name);

// The user's config file when none is named: $XDG_CONFIG_HOME/obscura/obscura.cfg (or ~/.config/...).
std::string defaultConfigPath();
// A config file's text with `values` set: lines for those keys are rewritten in place (the last one
// if a key repeats), missing keys appended; comments, blank lines and every other key are kept.
std::string updateConfigText(const std::string& text, const std::vector<std::pair<std::string, std::string>>& values);

// A config file is read only if it is a regular file of at most this size.
constexpr std::size_t kMaxConfigBytes = 1u << 20;

// Throws SettingsError if two actions share a key, naming the setting (and its file:line) that
// made the second binding. parse() calls it once everything is read, so a file may swap two keys.
void checkBindings(const Settings& s);

// The settings that change how input becomes movement, as `key value` pairs: mouse-sensitivity,
// invert-mouse and every bind-*. A recording carries them (replay `setting` headers).
std::vector<std::pair<std::string, std::string>> inputSettingValues(const Settings& s);

// Where setting `key` came from, as errors name it: "file:line", or "command line".
std::string sourceOf(const Settings& s, const std::string& key);

// Before a run starts: --screenshot's and --record's folders can take a new file, and a replay's
// --capture-dir can be made and written. Throws SettingsError naming the setting and the path.
void checkOutputsWritable(const Settings& s);

// Once the level is loaded: --start-pose (or a replay's start) and --smoke-at lie within the
// level's brushes plus map::kPlacementMargin. Throws SettingsError naming where the value came from.
void checkInLevel(const Settings& s, const map::Level& level);

class SettingsParser {
public:
    SettingsParser();
    ~SettingsParser();

    // Parses argv, then the config file (explicit --config, or none). Command-line values win.
    // Returns false if --help was printed.
    bool parse(int argc, const char* const argv[], Settings& out);
    // The text of a config file (`key = value` lines, # comments) applied onto `out`; errors name
    // fileName:line. parse() reads the file (size-capped) and calls this.
    void parseConfigText(const std::string& text, const std::string& fileName, Settings& out) const;
    // Applies one `key value` at run time (replay `set`, the menu). Throws SettingsError. A
    // bind-* to a key another action holds swaps the two actions' keys.
    void apply(const std::string& key, const std::string& value, Settings& s, const std::string& where) const;
    bool isKnown(const std::string& key) const;
    // Known and changeable while the game runs (not level, resolution, paths...).
    bool isRuntime(const std::string& key) const;
    std::string help() const;

private:
    struct Impl;
    Impl* impl_;
};

}  // namespace obscura
