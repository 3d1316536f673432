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
#include "map/liquid.h"
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
    // Quake figures in metres at the map scale (engine_ext/map/level.h: 32 Quake units a metre).
    // Step: Quake's 18 units (STEPSIZE in sv_phys.c / Quake III's bg_local.h) = 0.5625 m, so the
    // standard 16-unit risers (0.5 m) of id and TrenchBroom maps climb without a jump; 19 units do
    // not. A 0.75 m crate (24 units) is not a step.
    double stepHeight = 18.0 / 32.0;
    double maxSlopeDegrees = 46;  // walkable up to just past 45 degree ramps (brush-built ramps are often exactly 45)
    // Speeds (m/s), Quake's defaults: walking at cl_forwardspeed 200 u/s = 6.25 m/s; Shift is
    // Quake's +speed (its default Shift binding, cl_movespeedkey 2), which runs at the sv_maxspeed
    // cap of 320 u/s = 10 m/s, hence the multiplier 320 / 200 = 1.6 (jumps built for Quake are made
    // at that speed). Crouch-walk 2.5 m/s (80 u/s; Quake has none, Half-Life's is about 3.3 m/s).
    double walkSpeed = 200.0 / 32.0, sprintMultiplier = 320.0 / 200.0, crouchSpeed = 2.5;
    // Quake III's pm_accelerate 10 / pm_friction 6; air control 1.5 (Q3's 1, a little more so a
    // jump can be steered round a pillar); stopSpeed 2 m/s (64 u/s, below Q3's 100 u/s = 3.1 m/s)
    // stops in a few ticks without a dead stop.
    double groundAccel = 10, airAccel = 1.5, friction = 6, stopSpeed = 2.0;
    // Quake's sv_gravity 800 u/s^2 = 25 m/s^2 for the player. (Props and grenades fall at
    // kBodyGravity, physics_world.h: their throws and shoves were tuned for it.)
    double gravity = 800.0 / 32.0;
    // Quake's jump: 270 u/s straight up (QuakeC client.qc PlayerJump; Quake III's JUMP_VELOCITY)
    // = 8.4375 m/s; the apex is v^2 / 2g = 45.6 units = 1.42 m, so Quake's jumps are makeable;
    // clears a 0.75 m crate and a 1 m sill with room for the round bottom to get over the edge.
    double jumpSpeed = 270.0 / 32.0;
    double maxFallSpeed = 50;  // terminal velocity (Quake's sv_maxvelocity 2000 u/s is 62 m/s)
    // Most force (N) the player shoves a crate with, towards its own walking speed: beats a 20 kg
    // crate's friction (0.56 * 20 kg * kBodyGravity 20 m/s^2 = 224 N) with room, not a 60 kg one's (672 N).
    double pushForce = 600;
};

// Swimming (the last section of player_controller.cpp), after Quake III's PM_WaterMove / PM_CheckWaterJump (bg_pmove.c) and
// Quake's SV_WaterMove (sv_user.c). Kept apart from PlayerTuning so the ground constants can change
// without touching these.
struct SwimTuning {
    // Quake's swim speed is 0.7 of the run speed (SV_WaterMove's `wishspeed *= 0.7`); wading
    // (feet in) scales down towards it by the water level as Quake III does: 1 - 0.3 x level / 3.
    double swimScale = 0.7;
    double waterAccel = 4;     // Quake III's pm_wateraccelerate
    double waterFriction = 1;  // Quake III's pm_waterfriction, x the water level (1..3)
    // Idle in water the player drifts down at Quake's 60 u/s (SV_WaterMove: wishvel[2] -= 60), in
    // the level's units like the walk: 1.875 m/s at 32 units a metre.
    double sinkSpeed = 60.0 / 32.0;
    // Jumping out at an edge (PM_CheckWaterJump): waist in, a wall ahead within reach at the
    // waist, nothing ahead half a metre higher: out at 3.1 m/s forward (Quake III's 200 of 320
    // u/s) and 7.7 m/s up, an apex of 1.5 m: the feet, 0.9 m below the surface, clear a rim 0.25 m
    // above it with room. Reach: Quake III looks 30 units from the centre, 14 beyond its 16-unit
    // half-width: 0.45 m beyond the capsule. The jump's control lock ends when it starts to fall
    // or after Quake III's 2 s.
    double waterJumpForward = 3.1, waterJumpUp = 7.7;
    double waterJumpReach = 0.45, waterJumpClearance = 0.5, waterJumpMaxTime = 2.0;
};

struct PlayerState {
    Vec3 feet;      // bottom of the capsule, metres
    Vec3 velocity;  // m/s
    float yaw = 0, pitch = 0;  // radians; yaw about +Y, 0 = facing -Z; pitch positive looks up
    bool onGround = false, crouching = false;
    float height = 1.8f;        // current capsule height
    float eyeBelowTop = 0.15f;  // from the tuning, so eye() needs no controller
    // Liquids (Quake's waterlevel): 0 dry, 1 feet in, 2 waist in (swimming), 3 eyes under.
    int waterLevel = 0;
    map::LiquidKind liquid = map::LiquidKind::None;  // the liquid at the feet (the worst one)
    float waterJumpTime = 0;  // > 0: jumping out of the water at an edge, no control (seconds left)
    int health = 100;         // slime and lava take it (Simulation); at 0 the player respawns
    Vec3 eye() const { return feet + Vec3{0, static_cast<double>(height - eyeBelowTop), 0}; }
};

class PlayerController {
public:
    explicit PlayerController(PhysicsWorld& world, PlayerTuning tuning = {}, SwimTuning swim = {});
    PlayerController(const PlayerController&) = delete;
    PlayerController& operator=(const PlayerController&) = delete;

    const PlayerTuning& tuning() const { return tuning_; }
    // A fresh standing player at `feet` looking along `yaw`, `pitch`.
    PlayerState spawn(const Vec3& feet, double yaw, double pitch) const;
    // One fixed tick. Pushes crates it walks into (impulses on the world's bodies).
    void step(PlayerState& s, const PlayerCommand& cmd, double dt);
    // The level's liquids (none by default); must outlive the controller.
    void setLiquids(const map::LiquidQuery* liquids) { liquids_ = liquids; }
    const SwimTuning& swimTuning() const { return swim_; }
    // Quake's waterlevel of a body standing at `feet`, `height` tall with its eye at `eye`, and the
    // liquid there.
    int waterLevel(const Vec3& feet, double height, const Vec3& eye, map::LiquidKind* kind) const;

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
    // Swimming (the last section of player_controller.cpp).
    void updateWaterLevel(PlayerState& s) const;
    bool checkWaterJump(const Body& b, const PlayerState& s, const Vec3& flatForward) const;
    void waterMove(const Body& b, PlayerState& s, const PlayerCommand& cmd, double dt, Move& m) const;
    double wadeScale(int waterLevel) const;  // the wish speed's scale, 1 when dry
    void applyWaterFriction(Vec3& vel, int waterLevel, double dt) const;

    PhysicsWorld& world_;
    PlayerTuning tuning_;
    SwimTuning swim_;
    const map::LiquidQuery* liquids_ = nullptr;
    btCapsuleShape standShape_, crouchShape_;
    double minWalkNormalY_;
};

}  // namespace obscura::sim
