// See player_controller.h.
#include "sim/player_controller.h"

#include <algorithm>
#include <cmath>

namespace obscura::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Distance kept between the body and what it touched, so the next sweep never starts in
// contact (Bullet then reports fraction 0 and the player would stick). 5 mm is invisible.
constexpr double kSkin = 0.005;
// A ground probe this far below the feet decides "on ground" (covers the skin and float noise).
constexpr double kGroundProbe = 0.03;
// Pitch stops just short of straight up/down, where yaw would become ill-defined.
constexpr double kMaxPitch = 89.0 * kPi / 180.0;
// Grounded this few ticks ago and not rising: still follow the ground down. Covers a flat-bottomed
// body grazing a stair's edge for a tick on the way down.
constexpr int kFollowGroundTicks = 2;
// Slide iterations per move: Quake's 4 handles a corner between two walls and a floor.
constexpr int kSlideIterations = 4;

Vec3 horizontal(const Vec3& v) { return {v.x, 0, v.z}; }

void accelerate(Vec3& vel, const Vec3& wishDir, double wishSpeed, double accel, double dt) {
    const double current = dot(vel, wishDir);
    const double add = wishSpeed - current;
    if (add <= 0) return;
    vel += wishDir * std::min(accel * dt * wishSpeed, add);
}

// Removes the part of v going into the plane (with a hair of overbounce, as Quake's ClipVelocity).
Vec3 clipToPlane(const Vec3& v, const Vec3& n) {
    const double into = dot(v, n);
    if (into >= 0) return v;
    return v - n * (into * 1.001);
}
}  // namespace

PlayerController::PlayerController(PhysicsWorld& world, PlayerTuning tuning)
    : world_(world),
      tuning_(tuning),
      standShape_(btVector3(static_cast<btScalar>(tuning.radius), static_cast<btScalar>(tuning.standHeight / 2),
                            static_cast<btScalar>(tuning.radius))),
      crouchShape_(btVector3(static_cast<btScalar>(tuning.radius), static_cast<btScalar>(tuning.crouchHeight / 2),
                             static_cast<btScalar>(tuning.radius))),
      minWalkNormalY_(std::cos(tuning.maxSlopeDegrees * kPi / 180.0)) {
    // Bullet rounds a cylinder's edges by its margin (embedded in the extents); 1 cm keeps GJK
    // stable while the bottom stays flat enough to stand on a step's edge.
    standShape_.setMargin(0.01f);
    crouchShape_.setMargin(0.01f);
}

bool PlayerController::walkable(const Vec3& n) const { return n.y >= minWalkNormalY_; }

std::optional<SweepHit> PlayerController::groundBelow(const btCylinderShape& shape, const Vec3& centre, double distance) const {
    return world_.sweep(shape, centre, centre - Vec3{0, distance, 0});
}

PlayerController::MoveResult PlayerController::slideMove(const btCylinderShape& shape, Vec3 centre, Vec3 velocity,
                                                         double dt) const {
    MoveResult r;
    Vec3 delta = velocity * dt;
    Vec3 planes[kSlideIterations];
    int planeCount = 0;
    for (int iter = 0; iter < kSlideIterations; ++iter) {
        const double dist = length(delta);
        if (dist < 1e-7) break;
        const auto hit = world_.sweep(shape, centre, centre + delta);
        if (!hit) {
            centre += delta;
            break;
        }
        const Vec3 dir = delta / dist;
        const double travel = std::max(0.0, hit->fraction * dist - kSkin);
        centre += dir * travel;
        if (!walkable(hit->normal)) r.blocked = true;
        Vec3 remaining = delta * (1.0 - hit->fraction);
        const Vec3 n = hit->normal;
        remaining = clipToPlane(remaining, n);
        velocity = clipToPlane(velocity, n);
        // Two planes meeting in a crease: move along the crease only.
        for (int p = 0; p < planeCount; ++p) {
            if (dot(remaining, planes[p]) < 0) {
                const Vec3 crease = normalize(cross(planes[p], n));
                remaining = crease * dot(remaining, crease);
                velocity = crease * dot(velocity, crease);
                break;
            }
        }
        planes[planeCount++] = n;
        delta = remaining;
    }
    r.centre = centre;
    r.velocity = velocity;
    return r;
}

void PlayerController::pushBodies(const btCylinderShape& shape, const Vec3& centre, const Vec3& wish, double dt) const {
    if (length(wish) < 1e-6) return;
    const Vec3 dir = normalize(wish);
    // Probe a little further than the skin: a crate we are leaning on gets pushed.
    const auto hit = world_.sweep(shape, centre, centre + dir * (kSkin * 4 + tuning_.walkSpeed * dt));
    if (!hit || hit->dynamicBody < 0) return;
    btRigidBody& body = world_.dynamicBody(static_cast<std::size_t>(hit->dynamicBody));
    body.activate(true);
    body.applyCentralImpulse(toBt(dir * tuning_.pushImpulse));
}

void PlayerController::step(PlayerState& s, const PlayerCommand& cmd, double dt) {
    const PlayerTuning& t = tuning_;
    // View angles.
    s.yaw = static_cast<float>(std::remainder(static_cast<double>(s.yaw) + cmd.yawDelta, 2 * kPi));
    s.pitch = static_cast<float>(std::clamp(static_cast<double>(s.pitch) + cmd.pitchDelta, -kMaxPitch, kMaxPitch));

    // Crouch now; stand up only where the head has room.
    if (cmd.crouch && !s.crouching) {
        s.crouching = true;
    } else if (!cmd.crouch && s.crouching) {
        const Vec3 c = s.feet + Vec3{0, t.crouchHeight / 2, 0};
        if (!world_.sweep(crouchShape_, c, c + Vec3{0, t.standHeight - t.crouchHeight, 0})) s.crouching = false;
    }
    const double h = s.crouching ? t.crouchHeight : t.standHeight;
    s.height = static_cast<float>(h);
    s.eyeBelowTop = static_cast<float>(t.eyeBelowTop);
    const btCylinderShape& shape = s.crouching ? crouchShape_ : standShape_;
    Vec3 centre = s.feet + Vec3{0, h / 2, 0};

    // On the ground unless rising from a jump; walking up a ramp keeps vertical speed at zero.
    const auto ground = groundBelow(shape, centre, kGroundProbe);
    bool onGround = ground && walkable(ground->normal) && s.velocity.y <= 0.5;
    Vec3 groundNormal = onGround ? ground->normal : Vec3{0, 1, 0};
    if (!onGround && s.airTicks <= kFollowGroundTicks && s.velocity.y <= 0) {
        // Grounded last tick but the support just ended (a stair's edge): follow the ground down.
        if (const auto below = groundBelow(shape, centre, t.stepHeight); below && walkable(below->normal)) {
            centre.y -= std::max(0.0, below->fraction * t.stepHeight - kSkin);
            onGround = true;
            groundNormal = below->normal;
        }
    }

    // Wished motion on the horizontal plane.
    const double sy = std::sin(static_cast<double>(s.yaw)), cy = std::cos(static_cast<double>(s.yaw));
    const Vec3 forward{-sy, 0, -cy}, right{cy, 0, -sy};
    Vec3 wish = forward * cmd.forward + right * cmd.right;
    const double wishLen = length(wish);
    if (wishLen > 1) wish = wish / wishLen;
    const double speed = s.crouching ? t.crouchSpeed : (cmd.sprint ? t.sprintSpeed : t.walkSpeed);
    const double wishSpeed = std::min(wishLen, 1.0) * speed;
    const Vec3 wishDir = wishLen > 1e-9 ? wish / wishLen : Vec3{};

    Vec3 vel = s.velocity;
    bool jumped = false;
    if (onGround) {
        const double hs = length(horizontal(vel));
        if (hs > 0) {
            const double drop = std::max(hs, t.stopSpeed) * t.friction * dt;
            const double scale = std::max(hs - drop, 0.0) / hs;
            vel.x *= scale;
            vel.z *= scale;
        }
        accelerate(vel, wishDir, wishSpeed, t.groundAccel, dt);
        // Run along the ground plane at full speed, up or down a ramp (Quake's PM_GroundMove).
        vel.y = 0;
        const double groundSpeed = length(vel);
        vel = clipToPlane(vel, groundNormal);
        if (length(vel) > 1e-9) vel = normalize(vel) * groundSpeed;
        if (cmd.jump) {
            vel.y = 0;
            vel.y = std::sqrt(2 * t.gravity * t.jumpHeight);
            onGround = false;
            jumped = true;
        }
    } else {
        accelerate(vel, wishDir, wishSpeed, t.airAccel, dt);
        vel.y = std::max(vel.y - t.gravity * dt, -t.maxFallSpeed);
    }

    const bool wasOnGround = onGround;
    MoveResult moved = slideMove(shape, centre, vel, dt);

    // Step up: if a wall stopped a walk, try the same move from stepHeight higher, then settle down.
    if (wasOnGround && moved.blocked) {
        Vec3 up = centre + Vec3{0, t.stepHeight, 0};
        if (const auto ceiling = world_.sweep(shape, centre, up))
            up = centre + Vec3{0, std::max(0.0, ceiling->fraction * t.stepHeight - kSkin), 0};
        const MoveResult over = slideMove(shape, up, horizontal(vel), dt);
        const double drop = over.centre.y - centre.y + kGroundProbe;
        if (const auto land = groundBelow(shape, over.centre, drop); land && walkable(land->normal)) {
            const Vec3 landed = over.centre - Vec3{0, std::max(0.0, land->fraction * drop - kSkin), 0};
            if (length(horizontal(landed - centre)) > length(horizontal(moved.centre - centre)) + 1e-4) {
                moved.centre = landed;
                moved.velocity = Vec3{over.velocity.x, 0, over.velocity.z};
            }
        }
    }

    // Stay on the ground walking down stairs and ramps.
    if (wasOnGround && !jumped) {
        if (const auto below = groundBelow(shape, moved.centre, t.stepHeight); below && walkable(below->normal))
            moved.centre.y -= std::max(0.0, below->fraction * t.stepHeight - kSkin);
    }

    centre = moved.centre;
    vel = moved.velocity;
    const auto after = groundBelow(shape, centre, kGroundProbe);
    s.onGround = !jumped && after && walkable(after->normal) && (wasOnGround || vel.y <= 0.5);
    // On the ground the vertical speed is the ground's business (ramps, stairs): keep it zero,
    // so the next tick starts grounded; landing from a fall also ends here.
    if (s.onGround) vel.y = 0;
    s.airTicks = s.onGround ? 0 : s.airTicks + 1;
    s.velocity = vel;
    s.feet = centre - Vec3{0, h / 2, 0};

    pushBodies(shape, centre, wish, dt);
}

}  // namespace obscura::sim
