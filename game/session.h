// One game session in plain C++ (no OGRE): the level, its misc_model colliders read by
// engine_ext/mesh, the simulation, the smoke, the decals and the little presentation state that follows
// the ticks (the previous player pose for interpolation, the HUD's hit marker). The game owns it
// and advances it one tick at a time; rendering, sound and the HUD only read it.
#pragma once

#include "lightbake/bake_cache.h"
#include "core/triangle_mesh.h"
#include "core/vec3.h"
#include "game_decals.h"
#include "game_signs.h"
#include "game_smoke.h"
#include "map/level.h"
#include "map/load_report.h"
#include "settings.h"
#include "sim/player_controller.h"
#include "sim/simulation.h"
#include "tick_durations.h"

#include <memory>
#include <string>
#include <vector>

namespace obscura {

class Session {
public:
    // Reads and compiles settings.level (throws map/IO errors naming the file); `times`, when
    // given, gets the parse and compile milliseconds.
    static map::Level loadLevel(const Settings& settings, std::vector<std::string>* warnings, map::LoadTimes* times = nullptr);
    // The folders a relative misc_model path is looked for in: the .map file's, the data folder,
    // the working directory (the renderer places the visible model from the same list).
    static std::vector<std::string> modelSearchDirs(const Settings& settings);

    // Builds the colliders, the simulation and the smoke for `level`. towardSun (unit) is the
    // light the smoke's self-shadow is computed for. Throws at load time: a missing or malformed
    // model, a bad level or tick rate.
    Session(const Settings& settings, map::Level level, const Vec3& towardSun);
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    // One fixed tick: the simulation, then the smoke, the decals, the signs' holes and the hit marker
    // from its events.
    void step(const sim::PlayerCommand& cmd);
    void spawnSmoke(const Vec3& where) { smoke_.spawn(where); }

    const map::Level& level() const { return level_; }
    const sim::Simulation& sim() const { return sim_; }
    const GameSmoke& smoke() const { return smoke_; }
    const GameDecals& decals() const { return decals_; }
    const GameSigns& signs() const { return signs_; }
    const lightbake::LightBake& light() const { return light_.bake; }
    const std::vector<sim::SimEvent>& events() const { return sim_.events(); }
    std::uint64_t tick() const { return sim_.tick(); }
    const TickDurations& durations() const { return durations_; }
    // The player before the last tick (the view interpolates from it to sim().player()).
    const sim::PlayerState& previousPlayer() const { return previousPlayer_; }
    // The movers' offsets before the last tick (sim().movers() order), for the same interpolation.
    const std::vector<Vec3>& previousMoverOffsets() const { return previousMoverOffsets_; }
    double hitMarker() const { return hitMarker_; }
    // The `message` Quake would centre-print now (an entity's that used its targets), lines split
    // at '\n'; empty when none shows. (The level's title, worldspawn's message, goes to the load
    // line and the window's title, as Quake prints it to the console: not into every capture.)
    const std::string& centreMessage() const { return centreTicks_ > 0 ? centreMessage_ : kNoMessage; }
    // The trigger_changelevel the player touched, if any (its `map` is the next level); the game
    // acts on it after the tick.
    const map::LevelEntity* changeLevel() const {
        return changeLevel_ < 0 ? nullptr : &level_.entities.at(static_cast<std::size_t>(changeLevel_));
    }

private:
    void showMessage(const std::string& value);

    map::Level level_;
    TickDurations durations_;
    std::vector<TriangleMesh> colliders_;  // the misc_models' triangles, world space
    sim::Simulation sim_;
    GameSmoke smoke_;
    GameDecals decals_;
    GameSigns signs_;
    lightbake::BakeOutcome light_;  // the level's static light (engine_ext/lightbake), from the cache or baked
    sim::PlayerState previousPlayer_;
    std::vector<Vec3> previousMoverOffsets_;
    double hitMarker_ = 0;  // 1 at a hit, fading over kHitMarkerFadeSeconds
    std::string centreMessage_;
    int centreTicks_ = 0;   // ticks it still shows (durations_.centrePrintTicks after it is set)
    int changeLevel_ = -1;  // entity index of the trigger_changelevel touched
    int worldtype_ = 0;     // worldspawn's `worldtype` (Quake's key words: 0 key, 1 runekey, 2 keycard)
    static inline const std::string kNoMessage;
};

// "x y z" (validated by the settings table already).
Vec3 parseVec3(const std::string& text);

}  // namespace obscura
