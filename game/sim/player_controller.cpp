// See player_controller.h.
#include "sim/player_controller.h"

#include <algorithm>
#include <cmath>

namespace obscura::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;
const Vec3 kUp{0, 1, 0};
// Gap kept between the capsule and what it touched, so the next sweep does not start in contact
// (Bullet then reports fraction 0 and the player would stick). 5 mm is invisible.
constexpr double kSkin = 0.005;
// A ground probe this far below the capsule decides "on ground": covers the skin and float noise.
constexpr double kGroundProbe = 0.03;
// Sweep hits within 1 cm of the nearest are touched together (a floor meeting a slope's foot):
// any of them may hold the player up.
constexpr double kGroundTolerance = 0.01;
// Moving away from the ground faster than this (m/s) is leaving it: a jump, a launch off a ramp.
// Quake III's 10 u/s; the 1.001 overclip of a landing leaves a few cm/s, well below.
constexpr double kLeaveGroundSpeed = 0.3;
// Overlaps (a crate shoved into the player, a start pose inside a wall, float creep) are pushed
// out along the deepest contact's normal, one at a time; 4 covers a corner of walls and floor.
constexpr int kDepenetrationIterations = 4;
// Pitch stops just short of straight up/down, where yaw would become ill-defined.
constexpr double kMaxPitch = 89.0 * kPi / 180.0;
// Slide iterations per sub-step: Quake's 4 handles a corner between two walls and a floor.
constexpr int kSlideIterations = 4;
// A sub-step moves at most half the radius, so a fast fall is split into short sweeps; the cap
// bounds the work at absurd speeds (terminal velocity at 60 Hz needs 5).
constexpr double kMaxSubstepRadii = 0.5;
constexpr int kMaxSubsteps = 32;
// Quake's overclip: push a hair off each plane, so float error never leaves motion into it.
constexpr double kOverclip = 1.001;
// Edge support: a contact on the round bottom's lower part (normal y >= 0.3, within 0.95 r of the
// axis, about how far a Quake box hangs over a ledge) holds the player if the surface 2 cm beyond
// the contact, read by a ray from 5 cm above it, is walkable and level with the contact.
constexpr double kMinEdgeNormalY = 0.3;
constexpr double kEdgeProbeOut = 0.02, kEdgeProbeUp = 0.05, kEdgeLevelTolerance = 0.01;
// Step-up moves forward at least this far, so a player pressing against a step from standstill
// (a few mm per tick) gets the capsule's round bottom over the edge far enough to stand on it.
constexpr double kMinStepForward = 0.05;
// Hull margins and the skin put a step's top a few mm off its nominal height.
constexpr double kStepHeightTolerance = 0.01;
// The stepped move must beat the plain one by more than float noise to be taken.
constexpr double kStepProgressEpsilon = 1e-4;

Vec3 horizontal(const Vec3& v) { return {v.x, 0, v.z}; }

double finiteOr0(double v) { return std::isfinite(v) ? v : 0.0; }

// Garbage in (NaN from a broken input device, out-of-range axes) must not reach the physics.
PlayerCommand sanitized(PlayerCommand c) {
    c.forward = static_cast<float>(std::clamp(finiteOr0(c.forward), -1.0, 1.0));
    c.right = static_cast<float>(std::clamp(finiteOr0(c.right), -1.0, 1.0));
    c.yawDelta = static_cast<float>(finiteOr0(c.yawDelta));
    c.pitchDelta = static_cast<float>(finiteOr0(c.pitchDelta));
    return c;
}

// Quake's PM_Accelerate: add speed along wishDir up to wishSpeed, at most accel * wishSpeed * dt.
void accelerate(Vec3& vel, const Vec3& wishDir, double wishSpeed, double accel, double dt) {
    const double add = wishSpeed - dot(vel, wishDir);
    if (add <= 0) return;
    vel += wishDir * std::min(accel * dt * wishSpeed, add);
}

// Removes the part of v going into the plane (Quake's PM_ClipVelocity).
Vec3 clipToPlane(const Vec3& v, const Vec3& n) {
    const double into = dot(v, n);
    return into >= 0 ? v : v - n * (into * kOverclip);
}

// Keeps v on the plane without losing speed (running up or down a ramp at full speed).
Vec3 alongPlane(const Vec3& v, const Vec3& n) {
    const double speed = length(v);
    const Vec3 p = v - n * dot(v, n);
    const double l = length(p);
    return l > 1e-9 ? p * (speed / l) : Vec3{};
}
}  // namespace

PlayerController::PlayerController(PhysicsWorld& world, PlayerTuning tuning, SwimTuning swim)
    : world_(world),
      tuning_(tuning),
      swim_(swim),
      // btCapsuleShape takes the cylinder part's height: total minus both caps.
      standShape_(static_cast<btScalar>(tuning.radius), static_cast<btScalar>(tuning.standHeight - 2 * tuning.radius)),
      crouchShape_(static_cast<btScalar>(tuning.radius), static_cast<btScalar>(tuning.crouchHeight - 2 * tuning.radius)),
      minWalkNormalY_(std::cos(tuning.maxSlopeDegrees * kPi / 180.0)) {}

PlayerController::Body PlayerController::body(bool crouching) const {
    return crouching ? Body{&crouchShape_, tuning_.crouchHeight} : Body{&standShape_, tuning_.standHeight};
}

PlayerState PlayerController::spawn(const Vec3& feet, double yaw, double pitch) const {
    PlayerState s;
    s.feet = feet;
    s.yaw = static_cast<float>(std::remainder(finiteOr0(yaw), 2 * kPi));
    s.pitch = static_cast<float>(std::clamp(finiteOr0(pitch), -kMaxPitch, kMaxPitch));
    s.height = static_cast<float>(tuning_.standHeight);
    s.eyeBelowTop = static_cast<float>(tuning_.eyeBelowTop);
    return s;
}

bool PlayerController::supportedAt(const Body& b, const Vec3& centre, const SweepHit& hit, Vec3& surfaceNormal,
                                   double& surfaceY) const {
    surfaceY = hit.point.y;
    if (walkable(hit.normal)) {
        surfaceNormal = hit.normal;
        return true;
    }
    if (hit.normal.y < kMinEdgeNormalY) return false;  // on the capsule's side: a wall or a slope
    // The round bottom rests on an edge: look at the surface just beyond the contact.
    const Vec3 sphere = centre - kUp * (b.height / 2 - tuning_.radius);
    const Vec3 out = horizontal(hit.point - sphere);
    if (length(out) < 1e-6) return false;
    const Vec3 from = hit.point + normalize(out) * kEdgeProbeOut + kUp * kEdgeProbeUp;
    const auto ray = world_.rayCast(from, from - kUp * (2 * kEdgeProbeUp));
    if (!ray || !walkable(ray->normal) || ray->point.y < hit.point.y - kEdgeLevelTolerance) return false;
    surfaceNormal = ray->normal;
    return true;
}

Vec3 PlayerController::depenetrate(const Body& b, Vec3 centre) const {
    for (int i = 0; i < kDepenetrationIterations; ++i) {
        const auto contacts = world_.contacts(*b.shape, centre, 0.0);
        const ShapeContact* deepest = nullptr;
        for (const auto& c : contacts)
            if (c.distance < 0 && (!deepest || c.distance < deepest->distance)) deepest = &c;
        if (!deepest) break;
        centre += deepest->normal * (kSkin - deepest->distance);
    }
    return centre;
}

PlayerController::Ground PlayerController::findGround(const Body& b, const Vec3& centre, double distance) const {
    Ground g;
    const auto hits = world_.sweepAll(*b.shape, centre, centre - kUp * distance);
    if (hits.empty()) return g;
    g.found = true;
    g.distance = hits.front().fraction * distance;
    g.normal = hits.front().normal;
    for (const auto& h : hits) {
        const double d = h.fraction * distance;
        if (d > g.distance + kGroundTolerance) break;
        Vec3 n;
        double y = 0;
        if (supportedAt(b, centre - kUp * d, h, n, y)) {
            g.walkable = true;
            g.normal = n;
            g.supportY = y;
            break;
        }
    }
    return g;
}

void PlayerController::slide(const Body& b, double dt, bool grounded, Move& m) const {
    Vec3 delta = m.moveVel * dt;
    Vec3 planes[kSlideIterations];
    int planeCount = 0;
    for (int iter = 0; iter < kSlideIterations; ++iter) {
        const double dist = length(delta);
        if (dist < 1e-7) return;
        const auto hit = world_.sweep(*b.shape, m.centre, m.centre + delta);
        if (!hit) {
            m.centre += delta;
            return;
        }
        // To the contact, then off the surface by the skin along its normal: the gap to what was
        // hit is the skin whatever the angle of approach, so sliding along it never grazes it.
        m.centre += delta * hit->fraction + hit->normal * kSkin;
        delta = delta * (1.0 - hit->fraction);
        Vec3 n = hit->normal;
        // On foot, a floor too steep to walk is a wall: sliding along it must not lift the player.
        if (grounded && n.y > 0 && !walkable(n)) n = normalize(horizontal(n));
        if (!walkable(n)) m.hitWall = true;
        if (hit->dynamicBody >= 0) m.contacts.push_back({hit->dynamicBody, n});

        delta = clipToPlane(delta, n);
        m.moveVel = clipToPlane(m.moveVel, n);
        m.vel = clipToPlane(m.vel, n);
        // Clipping against this plane may drive into an earlier one: then only the crease
        // between the two is free; into a third as well, nothing is (Quake's PM_SlideMove).
        for (int p = 0; p < planeCount; ++p) {
            if (dot(delta, planes[p]) >= 0) continue;
            const Vec3 crease = normalize(cross(planes[p], n));
            delta = crease * dot(delta, crease);
            m.moveVel = crease * dot(m.moveVel, crease);
            m.vel = crease * dot(m.vel, crease);
            for (int q = 0; q < planeCount; ++q) {
                if (q != p && dot(delta, planes[q]) < 0) {
                    m.moveVel = m.vel = Vec3{};
                    return;
                }
            }
            break;
        }
        planes[planeCount++] = n;
    }
}

void PlayerController::move(const Body& b, double dt, bool grounded, Move& m) const {
    const double dist = length(m.moveVel) * dt;
    const int substeps = std::clamp(static_cast<int>(std::ceil(dist / (kMaxSubstepRadii * tuning_.radius))), 1, kMaxSubsteps);
    for (int i = 0; i < substeps; ++i) slide(b, dt / substeps, grounded, m);
}

bool PlayerController::stepUp(const Body& b, double dt, const Move& start, Move& result) const {
    const double plainProgress = length(horizontal(result.centre - start.centre));
    Move m = start;
    // Up (as far as the ceiling allows), forward, then down onto walkable ground.
    double lift = tuning_.stepHeight;
    if (const auto ceiling = world_.sweep(*b.shape, m.centre, m.centre + kUp * lift))
        lift = std::max(0.0, ceiling->fraction * lift - kSkin);
    m.centre += kUp * lift;
    m.moveVel = horizontal(m.moveVel);
    m.vel = horizontal(m.vel);
    const double forward = length(m.moveVel) * dt;
    if (forward < 1e-9) return false;
    if (forward < kMinStepForward) m.moveVel = m.moveVel * (kMinStepForward / forward);
    move(b, dt, true, m);
    const Ground land = findGround(b, m.centre, lift + kGroundProbe);
    // A step is what the capsule stands on after the step-up, no higher than stepHeight: the round
    // bottom could otherwise perch on the edge of a ledge up to stepHeight + radius high.
    const double feetY = start.centre.y - b.height / 2;
    if (!land.walkable || land.supportY > feetY + tuning_.stepHeight + kStepHeightTolerance) return false;
    m.centre -= kUp * std::max(0.0, land.distance - kSkin);
    if (length(horizontal(m.centre - start.centre)) <= plainProgress + kStepProgressEpsilon) return false;
    result = m;
    return true;
}

void PlayerController::pushBodies(const std::vector<Contact>& contacts, const Vec3& wishDir, double wishSpeed,
                                  double dt) const {
    std::vector<int> pushed;
    for (const Contact& c : contacts) {
        if (std::find(pushed.begin(), pushed.end(), c.body) != pushed.end()) continue;  // once a tick
        const Vec3 away = horizontal(-c.normal);
        if (length(away) < 0.1) continue;  // standing on it or bumping it from below
        const Vec3 dir = normalize(away);
        const double into = dot(dir, wishDir);
        if (into <= 0) continue;  // brushed past it, not walking into it
        pushed.push_back(c.body);
        // Shove it towards the speed the player is walking into it at, with at most pushForce.
        btRigidBody& body = world_.dynamicBody(static_cast<std::size_t>(c.body));
        const double missing = wishSpeed * into - dot(fromBt(body.getLinearVelocity()), dir);
        const double impulse = std::min(tuning_.pushForce * dt, missing / body.getInvMass());
        if (impulse <= 0) continue;
        body.activate(true);
        body.applyCentralImpulse(toBt(dir * impulse));
    }
}

int PlayerController::standingOn(const PlayerState& s) const {
    const Body b = body(s.crouching);
    const Vec3 centre = s.feet + kUp * (b.height / 2);
    const auto hit = world_.sweep(*b.shape, centre, centre - kUp * kGroundProbe);
    return hit ? hit->dynamicBody : kNothing;
}

double PlayerController::penetration(const PlayerState& s, int userIndex) const {
    const Body b = body(s.crouching);
    double deepest = 0;
    for (const auto& c : world_.contacts(*b.shape, s.feet + kUp * (b.height / 2), 0.0))
        if ((userIndex == kAnyBody || c.dynamicBody == userIndex) && c.distance < 0) deepest = std::max(deepest, -c.distance);
    return deepest;
}

void PlayerController::step(PlayerState& s, const PlayerCommand& rawCmd, double dt) {
    const PlayerTuning& t = tuning_;
    const PlayerCommand cmd = sanitized(rawCmd);
    s.yaw = static_cast<float>(std::remainder(static_cast<double>(s.yaw) + cmd.yawDelta, 2 * kPi));
    s.pitch = static_cast<float>(std::clamp(static_cast<double>(s.pitch) + cmd.pitchDelta, -kMaxPitch, kMaxPitch));

    // Crouch at once; stand up only where the standing capsule fits (sweep the crouched one up).
    if (cmd.crouch) {
        s.crouching = true;
    } else if (s.crouching) {
        const Vec3 c = s.feet + kUp * (t.crouchHeight / 2);
        if (!world_.sweep(crouchShape_, c, c + kUp * (t.standHeight - t.crouchHeight))) s.crouching = false;
    }
    const Body b = body(s.crouching);
    s.height = static_cast<float>(b.height);
    s.eyeBelowTop = static_cast<float>(t.eyeBelowTop);

    Move m;
    m.centre = depenetrate(b, s.feet + kUp * (b.height / 2));
    // In a liquid up to the waist, or jumping out of one: swimming (the section at the end).
    s.feet = m.centre - kUp * (b.height / 2);
    updateWaterLevel(s);
    if (s.waterJumpTime > 0 || s.waterLevel >= 2) {
        waterMove(b, s, cmd, dt, m);
        return;
    }
    const Ground ground = findGround(b, m.centre, kGroundProbe);
    bool onGround = ground.walkable && dot(s.velocity, ground.normal) <= kLeaveGroundSpeed;

    // Wished motion: on the ground along its plane, in the air horizontal.
    const double sy = std::sin(static_cast<double>(s.yaw)), cy = std::cos(static_cast<double>(s.yaw));
    const Vec3 forward{-sy, 0, -cy}, right{cy, 0, -sy};
    Vec3 wish = forward * cmd.forward + right * cmd.right;
    const double wishLen = std::min(length(wish), 1.0);
    const Vec3 flatWishDir = normalize(wish);
    const double maxSpeed = s.crouching ? t.crouchSpeed : t.walkSpeed * (cmd.sprint ? t.sprintMultiplier : 1.0);
    const double wishSpeed = wishLen * maxSpeed * wadeScale(s.waterLevel);

    Vec3 vel = s.velocity;
    bool jumped = false;
    if (onGround) {
        // Friction on the ground speed (Quake's PM_Friction): below stopSpeed it stops as if at stopSpeed.
        const double speed = length(horizontal(vel));
        if (speed > 1e-9) vel *= std::max(speed - std::max(speed, t.stopSpeed) * t.friction * dt, 0.0) / speed;
        else vel = Vec3{};
        applyWaterFriction(vel, s.waterLevel, dt);  // wading
        const Vec3 wishDir = normalize(flatWishDir - ground.normal * dot(flatWishDir, ground.normal));
        accelerate(vel, wishDir, wishSpeed, t.groundAccel, dt);
        vel = alongPlane(vel, ground.normal);
        if (cmd.jump) {
            vel.y = t.jumpSpeed;
            onGround = false;
            jumped = true;
        }
    } else {
        applyWaterFriction(vel, s.waterLevel, dt);
        accelerate(vel, flatWishDir, wishSpeed, t.airAccel, dt);
    }
    m.vel = m.moveVel = vel;
    if (!onGround) {
        // Gravity, moving with the tick's mean vertical speed: exact for constant acceleration, so
        // jump heights and fall times do not depend on the tick rate.
        m.vel.y = std::max(vel.y - t.gravity * dt, -t.maxFallSpeed);
        m.moveVel.y = 0.5 * (vel.y + m.vel.y);
    }

    const Move start = m;
    move(b, dt, onGround, m);
    if (onGround && m.hitWall) stepUp(b, dt, start, m);

    bool grounded = false;
    if (onGround) {
        // Follow the ground down stairs and ramps; past a ledge higher than a step, fall.
        const Ground below = findGround(b, m.centre, t.stepHeight);
        if (below.walkable) {
            // Down to the skin above it; or back up to it once GJK noise in wall normals has pushed
            // a player grinding along a wall below half of it (hysteresis: standing still is still).
            if (below.distance > kSkin || below.distance < kSkin / 2) m.centre -= kUp * (below.distance - kSkin);
            m.vel = alongPlane(m.vel, below.normal);  // over a ramp's crest: keep running, don't launch
            grounded = true;
        }
    } else if (!jumped) {
        // Landing.
        const Ground below = findGround(b, m.centre, kGroundProbe);
        if (below.walkable && dot(m.vel, below.normal) <= kLeaveGroundSpeed) {
            m.centre -= kUp * std::max(0.0, below.distance - kSkin);
            m.vel = clipToPlane(m.vel, below.normal);
            grounded = true;
        }
    }
    s.onGround = grounded;
    s.velocity = m.vel;
    s.feet = m.centre - kUp * (b.height / 2);
    pushBodies(m.contacts, flatWishDir, wishSpeed, dt);
}

// ---- Swimming -----------------------------------------------------------------------------
// Quake III's PM_SetWaterLevel, PM_WaterMove, PM_CheckWaterJump and PM_WaterJumpMove (bg_pmove.c)
// and Quake's SV_WaterMove / SV_WaterJump (sv_user.c), on this controller's sweeps. Tuning in
// SwimTuning (player_controller.h).

namespace {
// The feet's probe sits this far above the capsule's bottom (Quake III's "mins + 1 unit"): a player
// standing on a pool's rim level with the surface is not wading.
constexpr double kFeetProbe = 0.03;
}  // namespace

int PlayerController::waterLevel(const Vec3& feet, double height, const Vec3& eye, map::LiquidKind* kind) const {
    if (kind) *kind = map::LiquidKind::None;
    if (!liquids_ || liquids_->empty()) return 0;
    const map::LiquidKind atFeet = liquids_->at(feet + kUp * kFeetProbe);
    if (atFeet == map::LiquidKind::None) return 0;
    if (kind) *kind = atFeet;
    // Waist: half the body (Quake III samples half the view height, 25 of 56 units).
    if (liquids_->at(feet + kUp * (height / 2)) == map::LiquidKind::None) return 1;
    return liquids_->at(eye) == map::LiquidKind::None ? 2 : 3;
}

void PlayerController::updateWaterLevel(PlayerState& s) const {
    map::LiquidKind kind = map::LiquidKind::None;
    s.waterLevel = waterLevel(s.feet, s.height, s.eye(), &kind);
    s.liquid = kind;
}

double PlayerController::wadeScale(int level) const {
    return 1.0 - (1.0 - swim_.swimScale) * std::clamp(level, 0, 3) / 3.0;
}

void PlayerController::applyWaterFriction(Vec3& vel, int level, double dt) const {
    if (level <= 0) return;
    const double speed = length(vel);
    if (speed < 1e-9) return;
    vel *= std::max(speed - speed * swim_.waterFriction * level * dt, 0.0) / speed;
}

bool PlayerController::checkWaterJump(const Body& b, const PlayerState& s, const Vec3& flatForward) const {
    if (s.waterLevel != 2) return false;
    const double reach = tuning_.radius + swim_.waterJumpReach;
    const Vec3 waist = s.feet + kUp * (b.height / 2);
    if (!world_.rayCast(waist, waist + flatForward * reach)) return false;  // no edge ahead
    const Vec3 high = waist + kUp * swim_.waterJumpClearance;
    return !world_.rayCast(high, high + flatForward * reach);  // and room above it
}

void PlayerController::waterMove(const Body& b, PlayerState& s, const PlayerCommand& cmd, double dt, Move& m) const {
    const double sy = std::sin(static_cast<double>(s.yaw)), cy = std::cos(static_cast<double>(s.yaw));
    const double sp = std::sin(static_cast<double>(s.pitch)), cp = std::cos(static_cast<double>(s.pitch));
    const Vec3 flatForward{-sy, 0, -cy}, right{cy, 0, -sy};
    const Vec3 forward{-sy * cp, sp, -cy * cp};  // swimming goes where the eye looks
    Vec3 vel = s.velocity;

    if (s.waterJumpTime <= 0 && cmd.forward > 0 && cmd.jump && checkWaterJump(b, s, flatForward)) {
        vel.y = swim_.waterJumpUp;
        s.waterJumpTime = static_cast<float>(swim_.waterJumpMaxTime);
    }
    if (s.waterJumpTime > 0) {
        // Out of the water: no control, the forward push kept every tick (Quake's SV_WaterJump)
        // while the wall clips it, gravity as in the air; over once it starts falling.
        const Vec3 push = flatForward * swim_.waterJumpForward;
        m.vel.x = push.x;
        m.vel.z = push.z;
        m.vel.y = std::max(vel.y - tuning_.gravity * dt, -tuning_.maxFallSpeed);
        m.moveVel = {push.x, 0.5 * (vel.y + m.vel.y), push.z};
        s.waterJumpTime = static_cast<float>(s.waterJumpTime - dt);
        if (m.vel.y < 0 || s.waterJumpTime <= 0) s.waterJumpTime = 0;
    } else {
        applyWaterFriction(vel, s.waterLevel, dt);
        // Wished velocity: the look direction and strafe, jump up, crouch down; idle: sink.
        Vec3 wish = forward * cmd.forward + right * cmd.right;
        if (cmd.jump) wish.y += 1;
        if (cmd.crouch) wish.y -= 1;
        const double maxSpeed = tuning_.walkSpeed * (cmd.sprint ? tuning_.sprintMultiplier : 1.0);
        const double wishLen = std::min(length(wish), 1.0);
        const Vec3 wishVel = wishLen > 1e-9 ? normalize(wish) * (wishLen * maxSpeed) : Vec3{0, -swim_.sinkSpeed, 0};
        const double wishSpeed = std::min(length(wishVel), maxSpeed * swim_.swimScale);
        accelerate(vel, normalize(wishVel), wishSpeed, swim_.waterAccel, dt);
        m.vel = m.moveVel = vel;  // no gravity: the water holds the player up
    }
    // Standing on the bottom, steps still climb (a pool's stairs lead out of it).
    const bool grounded = s.waterJumpTime <= 0 && findGround(b, m.centre, kGroundProbe).walkable;
    const Move start = m;
    move(b, dt, false, m);
    if (grounded && m.hitWall) stepUp(b, dt, start, m);
    const Ground below = findGround(b, m.centre, kGroundProbe);
    s.onGround = below.walkable && dot(m.vel, below.normal) <= kLeaveGroundSpeed;
    if (s.onGround && m.vel.y < 0) m.vel.y = 0;  // resting on the pool's floor
    s.velocity = m.vel;
    s.feet = m.centre - kUp * (b.height / 2);
    pushBodies(m.contacts, normalize(horizontal(m.moveVel)), length(horizontal(m.moveVel)), dt);
}

}  // namespace obscura::sim
