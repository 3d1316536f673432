// The smoke grenades in the game: a detonation event releases a volume (engine_ext/smoke) where the
// grenade lies, shots carve tunnels through every volume they cross, the player pushes the smoke as
// a moving obstacle, and the volumes step at a fixed rate inside the simulation tick (so a replay
// gives the same smoke every run). Rendering reads the result one way: uploaded to 3D textures and
// ray-marched by the frame's volumetrics stage (smoke::SmokeRender) against the scene depth.
#pragma once

#include "core/triangle_mesh.h"
#include "core/vec3.h"
#include "map/level.h"
#include "sim/sim_events.h"
#include "sim/simulation.h"
#include "smoke/smoke_manager.h"
#include "smoke/smoke_render.h"

#include <string>
#include <vector>

namespace obscura {

class GameSmoke {
public:
    GameSmoke(const map::Level& level, std::vector<TriangleMesh> meshes, const Vec3& towardSun, double tickSeconds);

    // Releases smoke at `where` now; false (with the reason on stderr) if no grid fits there.
    bool spawn(const Vec3& where);
    // Once per simulation tick, after it: its events and the player's body.
    // After each simulation tick: detonations spawn volumes, shots carve them; every third tick the
    // volumes step with the player, the props and the grenades pushing the smoke.
    void onTick(const std::vector<sim::SimEvent>& events, const sim::Simulation& sim);
    // Once per rendered frame: new fields to the GPU (when the smoke stepped).
    void render();
    // The frame's volumetrics stage that marches them.
    frame::Technique& technique() { return render_; }
    std::size_t volumeCount() const { return manager_.volumes().size(); }
    const smoke::SmokeManager& manager() const { return manager_; }

private:
    const map::Level& level_;
    std::vector<TriangleMesh> meshes_;
    Vec3 towardSun_;
    double tickSeconds_;
    smoke::SmokeManager manager_;
    smoke::SmokeRender render_;
    long ticks_ = 0;
    bool dirty_ = false;  // stepped since the last upload
};

}  // namespace obscura
