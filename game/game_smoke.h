// The smoke grenades in the game: a detonation event releases a volume (engine_ext/smoke) where the
// grenade lies, shots carve tunnels through every volume they cross, the player pushes the smoke as
// a moving obstacle, and the volumes step at a fixed rate of the simulation's ticks (so a replay
// gives the same smoke every run). The smoke's CPU work runs on a worker, one step behind the
// ticks (smoke/smoke_pipeline.h): a tick only queues what happened. Plain C++: rendering
// (app/render_view.h) reads the published frame one way, uploading it to 3D textures when its
// version changed, and never writes back.
#pragma once

#include "core/triangle_mesh.h"
#include "core/vec3.h"
#include "map/level.h"
#include "sim/sim_events.h"
#include "sim/simulation.h"
#include "smoke/smoke_dump.h"
#include "smoke/smoke_pipeline.h"

#include <cstdint>
#include <string>
#include <vector>

namespace obscura {

class GameSmoke {
public:
    // meshes: the misc_models' triangles (obstacles); towardSun: unit, for the self-shadow.
    // resolution: grid cells a side (32 or 64) over the same 16 m box.
    GameSmoke(const map::Level& level, std::vector<TriangleMesh> meshes, const Vec3& towardSun, double tickRate,
              int resolution = 64);

    // Releases smoke at `where` with the next step (a place where no grid fits: the reason on
    // stderr then, and no cloud).
    void spawn(const Vec3& where);
    // The signs' lamps (engine_ext/signs: SignSpec::lamp, lightColour x intensity, range): the
    // smoke shadows them in the signs' shafts. The level's lamps it takes itself.
    void setSignLamps(std::vector<smoke::SmokeLamp> lamps);
    // After each simulation tick: detonations spawn volumes, shots carve them; every
    // kSmokeStepSeconds (tick_durations.h) the volumes step with the player, the props and the
    // grenades pushing the smoke.
    void onTick(const std::vector<sim::SimEvent>& events, const sim::Simulation& sim);
    // The volumes after every step issued (waits for the worker: tests and dumps, not the frame).
    const smoke::SmokeManager& manager() { return pipeline_.settled(); }
    const smoke::SmokeSettings& settings() const { return settings_; }
    // What the renderer draws: the frame of the step before the last one issued.
    const smoke::SmokeFrame& frame() const { return pipeline_.published(); }
    // Counts the steps issued.
    std::uint64_t version() const { return version_; }
    // Milliseconds the last onTick took on the calling (render) thread: queueing, and at a step
    // boundary the wait for the worker's step before.
    double lastTickMs() const { return lastTickMs_; }
    // Seconds of game time the smoke has seen (the ray-march animates its noise with it).
    double seconds() const { return static_cast<double>(ticks_) * tickSeconds_; }
    // The grids the renderer marches now (frame()), their densities as its textures hold them, its
    // noise time and extinction: for tools/signref.
    smoke::SmokeDump dump() const;

private:
    const map::Level& level_;
    Vec3 towardSun_;
    double tickSeconds_;
    long ticksPerStep_;
    smoke::SmokeSettings settings_;
    smoke::SmokePipeline pipeline_;
    long ticks_ = 0;
    std::uint64_t version_ = 0;
    double lastTickMs_ = 0;
};

}  // namespace obscura
