// The smoke grenades in the game: a detonation event releases a volume (engine_ext/smoke) where the
// grenade lies, shots carve tunnels through every volume they cross, the player pushes the smoke as
// a moving obstacle, and the volumes step at a fixed rate inside the simulation tick (so a replay
// gives the same smoke every run). Plain C++: rendering (app/render_view.h) reads the result one
// way, uploading it to 3D textures when version() changed, and never writes back.
#pragma once

#include "core/triangle_mesh.h"
#include "core/vec3.h"
#include "map/level.h"
#include "sim/sim_events.h"
#include "sim/simulation.h"
#include "smoke/smoke_dump.h"
#include "smoke/smoke_manager.h"

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

    // Releases smoke at `where` now; false (with the reason on stderr) if no grid fits there.
    bool spawn(const Vec3& where);
    // After each simulation tick: detonations spawn volumes, shots carve them; every
    // kSmokeStepSeconds (tick_durations.h) the volumes step with the player, the props and the
    // grenades pushing the smoke.
    void onTick(const std::vector<sim::SimEvent>& events, const sim::Simulation& sim);
    std::size_t volumeCount() const { return manager_.volumes().size(); }
    const smoke::SmokeManager& manager() const { return manager_; }
    // Counts the steps: a renderer uploads the fields again when it changed.
    std::uint64_t version() const { return version_; }
    // Seconds of game time the smoke has seen (the ray-march animates its noise with it).
    double seconds() const { return static_cast<double>(ticks_) * tickSeconds_; }
    // The grids the renderer marches (the first SMOKE_MAX_VOLUMES, smoke_render.cpp), their
    // densities as its textures hold them, its noise time and extinction: for tools/signref.
    smoke::SmokeDump dump() const;

private:
    const map::Level& level_;
    std::vector<TriangleMesh> meshes_;
    Vec3 towardSun_;
    double tickSeconds_;
    long ticksPerStep_;
    smoke::SmokeManager manager_;
    long ticks_ = 0;
    std::uint64_t version_ = 0;
};

}  // namespace obscura
