// A kinematic capsule character controller, Quake-style (PM_SlideMove / PM_StepSlideMove in
// Quake III's bg_pmove.c and bg_slidemove.c) on Bullet convex sweeps instead of Quake's box
// traces: ground friction and acceleration, air control, gravity, jump, crouch, sprint;
// collide-and-slide against every surface it touches; step-up to `stepHeight`; ground snap going
// down stairs and ramps; slopes steeper than `maxSlopeDegrees` act as walls on foot and slide in
// the air. The capsule's round bottom meets a step's edge with a leaning contact normal; the
// surface under such an edge is read with a short ray ("edge support"), so steps and ledges hold
// the player while real slopes do not. Continuous sweeps plus sub-steps: it cannot tunnel.
// Not btKinematicCharacterController (which jitters and sinks on Bullet 3.x).
#pragma once

#include "core/vec3.h"
#include "sim/physics_world.h"

#include <vector>

namespace obscura::sim {

struct PlayerCommand {
    float forward = 0, right = 0;  // -1..1
    bool jump = false, crouch = false, sprint = false;
    float yawDelta = 0, pitchDelta = 0;  // radians this tick
    bool fire = false;       // trigger held
    bool reload = false;     // reload key held (acts on the press)
    bool throwHeld = false;  // grenade key held: charging; the release throws
};

struct PlayerTuning {
    // Body: 0.35 m radius fits a 0.8 m doorway with room; 1.8 m standing, 1.1 m crouched
    // (fits under a 1.2 m vent); the eye sits 0.15 m below the top of the head.
    double radius = 0.35, standHeight = 1.8, crouchHeight = 1.1, eyeBelowTop = 0.15;
    double stepHeight = 0.45;     // a knee-high step; stairs are 0.25 m, a crate (0.75 m) is not a step
    double maxSlopeDegrees = 46;  // walkable up to just past 45 degree ramps (brush-built ramps are often exactly 45)
    // Speeds (m/s): a brisk run (Quake's 320 u/s is 10 m/s at 32 u/m: too fast for indoor levels
    // in metres), sprint 1.5x, crouch-walk at half speed.
    double walkSpeed = 5.0, sprintMultiplier = 1.5, crouchSpeed = 2.5;
    // Quake III's pm_accelerate 10 / pm_friction 6; air control 1.5 (Q3's 1, a little more so a
    // jump can be steered round a pillar); stopSpeed 2 m/s (Q3's 100 u/s) stops in a few ticks.
    double groundAccel = 10, airAccel = 1.5, friction = 6, stopSpeed = 2.0;
    // Gravity 20 m/s^2, not 9.81: game jumps are higher and quicker than human ones, and at 9.81
    // a 1.1 m jump hangs for almost a second. Quake uses 800 u/s^2 = 25 m/s^2.
    double gravity = 20;
    // Apex of a standing jump (the jump speed is sqrt(2 g h) = 6.6 m/s): clears a 0.75 m crate
    // and a 1 m sill with 10 cm for the capsule's round bottom to get over the edge.
    double jumpHeight = 1.1;
    double maxFallSpeed = 50;  // terminal velocity (Quake's sv_maxvelocity 2000 u/s is 62 m/s)
    // Most force (N) the player shoves a crate with, towards its own walking speed: beats a 20 kg
    // crate's friction (0.56 * 20 kg * 20 m/s^2 = 224 N) with room, not a 60 kg one's (672 N).
    double pushForce = 600;
};

struct PlayerState {
    Vec3 feet;      // bottom of the capsule, metres
    Vec3 velocity;  // m/s
    float yaw = 0, pitch = 0;  // radians; yaw about +Y, 0 = facing -Z; pitch positive looks up
    bool onGround = false, crouching = false;
    float height = 1.8f;        // current capsule height
    float eyeBelowTop = 0.15f;  // from the tuning, so eye() needs no controller
    Vec3 eye() const { return feet + Vec3{0, static_cast<double>(height - eyeBelowTop), 0}; }
};

class PlayerController {
public:
    explicit PlayerController(PhysicsWorld& world, PlayerTuning tuning = {});
    PlayerController(const PlayerController&) = delete;
    PlayerController& operator=(const PlayerController&) = delete;

    const PlayerTuning& tuning() const { return tuning_; }
    // A fresh standing player at `feet` looking along `yaw`, `pitch`.
    PlayerState spawn(const Vec3& feet, double yaw, double pitch) const;
    // One fixed tick. Pushes crates it walks into (impulses on the world's bodies).
    void step(PlayerState& s, const PlayerCommand& cmd, double dt);

    // For movers (sim/movers.h). The user index of what the player stands on (the nearest body a
    // ground probe below the capsule meets), or kNothing.
    static constexpr int kNothing = -999, kAnyBody = -998;
    int standingOn(const PlayerState& s) const;
    // How deep (metres, 0 when clear) the capsule overlaps the body with user index `userIndex`,
    // or anything (kAnyBody).
    double penetration(const PlayerState& s, int userIndex) const;

private:
    struct Body {
        const btCapsuleShape* shape;
        double height;
    };
    struct Ground {
        bool found = false, walkable = false;
        double distance = 0;  // how far the capsule can move down before touching
        double supportY = 0;  // height of the supporting surface where it holds the capsule (walkable)
        Vec3 normal{0, 1, 0};  // the supporting surface's normal (walkable) or the nearest contact's
    };
    struct Contact {
        int body;
        Vec3 normal;
    };
    struct Move {
        Vec3 centre, moveVel, vel;  // moveVel: this tick's displacement / dt; vel: the end-of-tick velocity
        bool hitWall = false;       // stopped by something not walkable (a step-up candidate)
        std::vector<Contact> contacts;
    };

    Body body(bool crouching) const;
    bool walkable(const Vec3& n) const { return n.y >= minWalkNormalY_; }
    Vec3 depenetrate(const Body& b, Vec3 centre) const;
    Ground findGround(const Body& b, const Vec3& centre, double distance) const;
    bool supportedAt(const Body& b, const Vec3& centre, const SweepHit& hit, Vec3& surfaceNormal, double& surfaceY) const;
    void slide(const Body& b, double dt, bool grounded, Move& m) const;
    void move(const Body& b, double dt, bool grounded, Move& m) const;
    bool stepUp(const Body& b, double dt, const Move& start, Move& result) const;
    void pushBodies(const std::vector<Contact>& contacts, const Vec3& wishDir, double wishSpeed, double dt) const;

    PhysicsWorld& world_;
    PlayerTuning tuning_;
    btCapsuleShape standShape_, crouchShape_;
    double minWalkNormalY_;
};

}  // namespace obscura::sim
