// Combat in the simulation (plain C++ + Bullet, no OGRE): the hitscan rifle (fire rate, magazine,
// reload, spread and recoil from the simulation's seeded RNG), the range's targets (pop-up and
// moving, hit by the same rays, scored), grenade throwing (hold to throw further, a Bullet sphere
// that bounces and rolls, a fuse), and the movement sounds' cues (footsteps, jumps, landings).
// Everything that happens is reported as SimEvents; the game reads them one way.
#pragma once

#include "core/rng.h"
#include "core/state_hash.h"
#include "map/level.h"
#include "sim/physics_world.h"
#include "sim/player_controller.h"
#include "sim/sim_events.h"

#include <cstdint>
#include <vector>

namespace obscura::sim {

struct WeaponState {
    int magazine = 30, reserve = 120, magazineSize = 30;
    bool reloading = false;
    double reloadProgress = 0;  // 0..1 while reloading
    double spreadDegrees = 0;   // the cone the next shot is drawn from (half angle)
    double recoilDegrees = 0;   // view kick not yet recovered
    std::uint64_t shotsFired = 0, hits = 0;
};

struct TargetState {
    Vec3 base;          // where the entity stands (moving targets: the middle of their track)
    Vec3 position;      // the base now
    double yaw = 0;     // the board faces along yaw (level.h convention: 0 = -Z)
    double width = 0.6, height = 1.6;
    double raise = 1;   // 1 up, 0 down (animated)
    bool up = true;
    int health = 100;
    bool moving = false;
};

struct GrenadeState {
    int id = 0;
    Vec3 position;
    double qx = 0, qy = 0, qz = 0, qw = 1;
    double radius = 0.06;
    double fuseLeft = 0;  // seconds
    Vec3 velocity;        // m/s
};

class Combat {
public:
    // Reads target_popup / target_moving entities (throws SimError naming file:line:column for a
    // bad key). The physics world must outlive it.
    Combat(const map::Level& level, PhysicsWorld& physics, double tickRate);

    // One tick, after the player moved: the rifle, the grenade key, targets, grenades, movement cues.
    void step(const PlayerCommand& cmd, PlayerState& player, const PlayerState& before, Rng& rng,
              std::vector<SimEvent>& events);

    const WeaponState& weapon() const { return weapon_; }
    const std::vector<TargetState>& targets() const { return targets_; }
    int score() const { return score_; }
    double throwCharge() const { return charging_ ? charge_ : 0.0; }
    std::vector<GrenadeState> grenades() const;
    void hash(StateHasher& h) const;

    // Rifle constants (see combat.cpp for the reasons).
    static constexpr int kDamage = 34;
    static constexpr double kRange = 200;

private:
    void stepRifle(const PlayerCommand& cmd, PlayerState& player, Rng& rng, std::vector<SimEvent>& events);
    void shoot(PlayerState& player, Rng& rng, std::vector<SimEvent>& events);
    void stepTargets(std::vector<SimEvent>& events);
    void stepGrenades(const PlayerCommand& cmd, const PlayerState& player, std::vector<SimEvent>& events);
    void stepMovementCues(const PlayerState& player, const PlayerState& before, std::vector<SimEvent>& events);
    // Nearest up target the segment crosses: index and distance along it, or -1.
    int rayTarget(const Vec3& from, const Vec3& dir, double maxDist, double& dist, Vec3& normal) const;
    void detonate(int id, std::vector<SimEvent>& events);

    PhysicsWorld& physics_;
    double dt_;
    WeaponState weapon_;
    int cooldownTicks_ = 0, reloadTicks_ = 0;
    bool triggerWasDown_ = false, reloadWasDown_ = false, dryFired_ = false;
    double bloom_ = 0;  // degrees added by recent shots, decaying
    double sinceShot_ = 1e9;  // seconds since the last shot (recoil recovers after a pause)
    std::vector<TargetState> targets_;
    struct TargetMotion {
        double speed = 0, distance = 0;  // moving targets: m/s along a track this long
        double reset = 3;                // seconds down before rising again
        double phase = 0;                // metres travelled along the track
        double downTime = 0;             // seconds since it went down
    };
    std::vector<TargetMotion> motion_;
    int score_ = 0;
    bool charging_ = false;
    double charge_ = 0;
    struct Grenade {
        int body;
        double fuseLeft;
        Vec3 lastVelocity;
    };
    std::vector<Grenade> grenades_;  // oldest first
    double walked_ = 0;
    int footstep_ = 0;
};

}  // namespace obscura::sim
