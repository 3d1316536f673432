// A kinematic character controller in the manner of Quake's PM_SlideMove/PM_StepSlideMove, on
// Bullet sweeps of an upright cylinder (flat-bottomed like Quake's box hull, so a step's edge
// reads as a step, not as a slope under a rounded capsule; round like a capsule, so turning
// never changes what fits): ground friction and acceleration, air control, gravity, jump, crouch,
// sprint; collide-and-slide against every surface it touches; steps up to `stepHeight`; snaps to
// the ground going down stairs and ramps; slides down slopes steeper than `maxSlopeDegrees`.
// Continuous sweeps mean it cannot tunnel, whatever its speed.
#pragma once

#include "core/vec3.h"
#include "sim/physics_world.h"

namespace obscura::sim {

struct PlayerCommand {
    float forward = 0, right = 0;  // -1..1
    bool jump = false, crouch = false, sprint = false;
    float yawDelta = 0, pitchDelta = 0;  // radians this tick
};

struct PlayerTuning {
    // Body: 0.35 m radius fits a 0.8 m doorway with room; 1.8 m standing, 1.1 m crouched
    // (fits under a 1.2 m vent); the eye sits 0.15 m below the top of the head.
    double radius = 0.35, standHeight = 1.8, crouchHeight = 1.1, eyeBelowTop = 0.15;
    double stepHeight = 0.45;        // a knee-high step; stairs are 0.25 m
    double maxSlopeDegrees = 46;     // walkable up to just past 45 degree ramps
    // Speeds (m/s): a brisk run, a sprint, a crouch-walk.
    double walkSpeed = 5.0, sprintSpeed = 7.5, crouchSpeed = 2.5;
    // Quake's feel: sv_friction 4 / sv_accelerate 10 scaled to a snappier stop at 6.
    double groundAccel = 10, airAccel = 1.5, friction = 6, stopSpeed = 2.0;
    // Gravity 20 m/s^2 (Quake uses 25 at 32 units/m): snappy, but falls still read as falls.
    double gravity = 20;
    double jumpHeight = 1.0;         // apex of a standing jump: onto a 0.75 m crate with margin
    double maxFallSpeed = 50;        // terminal velocity
    double pushImpulse = 6;          // N*s per tick against a crate the player walks into
};

struct PlayerState {
    Vec3 feet;
    Vec3 velocity;
    float yaw = 0, pitch = 0;  // radians; yaw about +Y, 0 = facing -Z; pitch positive looks up
    bool onGround = false, crouching = false;
    int airTicks = 0;  // ticks since the player last stood on the ground
    float height = 1.8f;
    float eyeBelowTop = 0.15f;
    Vec3 eye() const { return feet + Vec3{0, static_cast<double>(height - eyeBelowTop), 0}; }
};

class PlayerController {
public:
    PlayerController(PhysicsWorld& world, PlayerTuning tuning = {});
    const PlayerTuning& tuning() const { return tuning_; }

    void step(PlayerState& s, const PlayerCommand& cmd, double dt);

private:
    struct MoveResult {
        Vec3 centre;
        Vec3 velocity;
        bool blocked = false;
    };
    MoveResult slideMove(const btCylinderShape& shape, Vec3 centre, Vec3 velocity, double dt) const;
    std::optional<SweepHit> groundBelow(const btCylinderShape& shape, const Vec3& centre, double distance) const;
    bool walkable(const Vec3& normal) const;
    void pushBodies(const btCylinderShape& shape, const Vec3& centre, const Vec3& wish, double dt) const;

    PhysicsWorld& world_;
    PlayerTuning tuning_;
    btCylinderShape standShape_, crouchShape_;
    double minWalkNormalY_;
};

}  // namespace obscura::sim
