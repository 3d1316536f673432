// The game simulation: the Bullet world built from a compiled level, the player, props and the
// seeded RNG, advanced one fixed tick at a time from player commands. It never reads render
// state; the game reads it (player state, body poses) and pushes it to rendering.
#pragma once

#include "core/rng.h"
#include "core/triangle_mesh.h"
#include "map/level.h"
#include "map/liquid.h"
#include "sim/combat.h"
#include "sim/entity_keys.h"
#include "sim/movers.h"
#include "sim/pickups.h"
#include "sim/physics_world.h"
#include "sim/player_controller.h"
#include "sim/sim_events.h"
#include "sim/triggers.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace obscura::sim {

struct SimConfig {
    double tickRate = 60;  // ticks per second
    std::uint64_t seed = 1;
    bool overrideStart = false;  // start at startFeet/startYaw/startPitch instead of the level's start
    Vec3 startFeet;
    double startYaw = 0, startPitch = 0;  // radians
};

class Simulation {
public:
    // A dynamic body's pose for rendering.
    struct BodyPose {
        enum class Shape { Box, Cylinder };  // cylinder: radius = halfExtents.x, half height = y, axis Y
        Vec3 position;
        double qx = 0, qy = 0, qz = 0, qw = 1;
        Vec3 halfExtents;
        Shape shape = Shape::Box;
        Vec3 velocity;  // m/s, of the centre
    };

    // modelMeshes: world-space triangles of the level's misc_models (static colliders).
    // Throws SimError on a malformed level (naming file:line:column) or a bad tick rate.
    Simulation(const map::Level& level, const SimConfig& config, const std::vector<TriangleMesh>& modelMeshes = {});

    void step(const PlayerCommand& cmd);

    std::uint64_t tick() const { return tick_; }
    double dt() const { return 1.0 / config_.tickRate; }
    const PlayerState& player() const { return player_; }
    Rng& rng() { return rng_; }
    PhysicsWorld& physics() { return *physics_; }
    const PhysicsWorld& physics() const { return *physics_; }
    std::vector<BodyPose> bodyPoses() const;
    // Moving brushes (doors, plats, buttons, trains) and triggers (sim/movers.h, sim/triggers.h).
    const Movers& movers() const { return *movers_; }
    const Triggers& triggers() const { return *triggers_; }
    const Pickups& pickups() const { return *pickups_; }
    // What the level's movers and triggers could not use ("file:line: classname: problem").
    const std::vector<std::string>& warnings() const { return warnings_; }

    // Combat (sim/combat.h) and what happened during the last step.
    const std::vector<SimEvent>& events() const { return events_; }
    const WeaponState& weapon() const { return combat_->weapon(); }
    const std::vector<TargetState>& targets() const { return combat_->targets(); }
    int score() const { return combat_->score(); }
    double throwCharge() const { return combat_->throwCharge(); }
    std::vector<GrenadeState> grenades() const { return combat_->grenades(); }

    // Liquids (map/liquid.h): the level's volumes; what slime and lava did to the player.
    const map::LiquidQuery& liquids() const { return liquids_; }
    int liquidDamage() const { return liquidDamage_; }  // health taken by slime and lava so far
    int deaths() const { return deaths_; }              // times the player died and respawned

    // Hash of everything that evolves: tick, player, every dynamic body, the movers and triggers, the RNG.
    std::uint64_t stateHash() const;
    std::string stateHashHex() const;

private:
    void applyLiquidDamage();
    void respawnIfDead();  // health at 0 or below (slime, lava, trigger_hurt): back to the start

    SimConfig config_;
    map::LiquidQuery liquids_;  // before controller_, which points at it
    std::unique_ptr<PhysicsWorld> physics_;
    std::unique_ptr<PlayerController> controller_;
    std::unique_ptr<Combat> combat_;
    std::vector<std::string> warnings_;
    std::unique_ptr<EntityKeys> keys_;
    std::unique_ptr<Movers> movers_;
    std::unique_ptr<Triggers> triggers_;
    std::unique_ptr<Pickups> pickups_;
    std::vector<SimEvent> events_;
    PlayerState player_;
    Rng rng_;
    std::uint64_t tick_ = 0;
    Vec3 startFeet_;                  // where a dead player respawns
    double startYaw_ = 0, startPitch_ = 0;
    std::uint64_t nextLiquidDamageTick_ = 0;  // Quake's dmgtime, in ticks
    int liquidDamage_ = 0, deaths_ = 0;
};

}  // namespace obscura::sim
