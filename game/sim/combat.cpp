// See combat.h.
#include "sim/combat.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace obscura::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// Rifle. 600 rounds a minute: an assault rifle's cyclic rate, and a whole number of ticks (6) at 60 Hz.
constexpr double kRoundsPerSecond = 10;
constexpr int kMagazine = 30, kReserve = 120;  // three reloads' worth, enough for the range
constexpr double kReloadSeconds = 2.0;         // long enough to matter, short enough not to annoy
// Spread (half angle, degrees): 0.2 standing still (hits a 30 cm board at 40 m), up to +1.8 at a
// run, +3.8 in the air; each shot blooms it by 0.35 (capped at 3), recovering at 4 a second.
constexpr double kSpreadStill = 0.2, kSpreadRunning = 1.8, kSpreadAir = 3.8;
constexpr double kBloomPerShot = 0.35, kBloomMax = 3.0, kBloomRecovery = 4.0;
// Recoil: 0.5 degrees up a shot with up to 0.15 sideways; once the rifle has been quiet for 0.15 s
// the view is pulled back down at 6 degrees a second (a full-auto burst climbs, a tap is back on
// the aim point a tenth of a second after the pause).
constexpr double kRecoilPitch = 0.5, kRecoilYaw = 0.15, kRecoilRecovery = 6.0, kRecoilPause = 0.15;
// 60 N s along the shot: gameplay, not ballistics (a real rifle bullet carries ~4 N s). Hit near
// its top, an empty 12 kg drum tips over; a 20 kg crate slides about a metre.
constexpr double kImpulse = 60;
// Targets: 34 damage against 100 health: three hits drop one (two would make the moving ones
// trivial, four would make the range a chore). +10 a hit, +50 for each one dropped.
constexpr int kTargetHealth = 100, kScoreHit = 10, kScoreDown = 50;
constexpr double kRaiseSpeed = 4.0;           // 1/s: a target falls or rises in a quarter second
constexpr double kTargetThickness = 0.05;     // m: a steel plate
// Grenades: hold up to 1 s; 7 m/s (a lob across a room) to 18 m/s (across the courtyard), thrown
// 8 degrees above the view from 0.4 m ahead of the eye. Fuse 2 s; at most 4 live.
constexpr double kChargeSeconds = 1.0, kThrowMin = 7, kThrowExtra = 11, kThrowLift = 8 * kDeg, kThrowAhead = 0.4;
constexpr double kGrenadeRadius = 0.06, kGrenadeMass = 0.4, kFuseSeconds = 2.0;
constexpr std::size_t kMaxGrenades = 4;
constexpr double kBounceSpeed = 1.0;  // m/s of velocity change in one tick (beyond gravity) = a bounce
// Movement cues: a footstep every 2.2 m walked (a stride at a run); a landing faster than 3 m/s thuds.
constexpr double kStride = 2.2, kLandSpeed = 3.0;

Vec3 forwardOf(double yaw, double pitch) {
    return {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}
Vec3 rightOf(double yaw) { return {std::cos(yaw), 0, -std::sin(yaw)}; }

std::string where(const map::Level& level, const map::SourcePos& pos) {
    return (level.sourcePath.empty() ? std::string("<level>") : level.sourcePath) + ":" + std::to_string(pos.line) + ":" +
           std::to_string(pos.column);
}

double numberKey(const map::Level& level, const map::LevelEntity& e, const char* key, double fallback, double lo, double hi) {
    if (!e.has(key)) return fallback;
    const std::string& text = e.value(key);
    double v = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size() || !(v > lo && v <= hi))
        throw SimError(where(level, e.pos) + ": " + e.classname + " key '" + key + "' is '" + text + "', expected a number in (" +
                       std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
}
}  // namespace

Combat::Combat(const map::Level& level, PhysicsWorld& physics, double tickRate) : physics_(physics), dt_(1.0 / tickRate) {
    weapon_.magazine = weapon_.magazineSize = kMagazine;
    weapon_.reserve = kReserve;
    for (const auto& e : level.entities) {
        const bool popup = e.classname == "target_popup", moving = e.classname == "target_moving";
        if (!popup && !moving) continue;
        if (!e.hasOrigin) throw SimError(where(level, e.pos) + ": " + e.classname + " without an 'origin'");
        TargetState t;
        t.base = t.position = e.origin;
        t.yaw = e.yaw;
        t.width = numberKey(level, e, "width", 0.6, 0.05, 10);
        t.height = numberKey(level, e, "height", 1.6, 0.05, 10);
        t.moving = moving;
        t.health = kTargetHealth;
        targets_.push_back(t);
        TargetMotion m;
        m.reset = numberKey(level, e, "reset", 3.0, 0, 600);
        if (moving) {
            m.speed = numberKey(level, e, "speed", 2.0, 0, 50);
            m.distance = numberKey(level, e, "distance", 6.0, 0, 200);
        }
        motion_.push_back(m);
    }
}

void Combat::step(const PlayerCommand& cmd, PlayerState& player, const PlayerState& before, Rng& rng,
                  std::vector<SimEvent>& events) {
    stepTargets(events);
    stepRifle(cmd, player, rng, events);
    stepGrenades(cmd, player, events);
    stepMovementCues(player, before, events);
}

void Combat::stepRifle(const PlayerCommand& cmd, PlayerState& player, Rng& rng, std::vector<SimEvent>& events) {
    // Recoil recovers, bloom decays, the spread follows how the player moves.
    sinceShot_ += dt_;
    const double recover = sinceShot_ >= kRecoilPause ? std::min(weapon_.recoilDegrees, kRecoilRecovery * dt_) : 0.0;
    weapon_.recoilDegrees -= recover;
    player.pitch -= static_cast<float>(recover * kDeg);
    bloom_ = std::max(0.0, bloom_ - kBloomRecovery * dt_);
    const double speed = std::hypot(player.velocity.x, player.velocity.z);
    weapon_.spreadDegrees = kSpreadStill + kSpreadRunning * std::min(speed / 5.0, 1.0) + (player.onGround ? 0.0 : kSpreadAir) + bloom_;

    if (cooldownTicks_ > 0) --cooldownTicks_;
    if (weapon_.reloading) {
        if (--reloadTicks_ <= 0) {
            const int moved = std::min(weapon_.magazineSize - weapon_.magazine, weapon_.reserve);
            weapon_.magazine += moved;
            weapon_.reserve -= moved;
            weapon_.reloading = false;
            weapon_.reloadProgress = 0;
            events.push_back(SimEvent::at(SimEventType::ReloadEnd, player.eye()));
        } else {
            weapon_.reloadProgress = 1.0 - static_cast<double>(reloadTicks_) / std::round(kReloadSeconds / dt_);
        }
    }
    const bool reloadPressed = cmd.reload && !reloadWasDown_;
    reloadWasDown_ = cmd.reload;
    const bool pressed = cmd.fire && !triggerWasDown_;
    triggerWasDown_ = cmd.fire;
    if (pressed) dryFired_ = false;
    auto startReload = [&] {
        weapon_.reloading = true;
        reloadTicks_ = static_cast<int>(std::round(kReloadSeconds / dt_));
        weapon_.reloadProgress = 0;
        events.push_back(SimEvent::at(SimEventType::ReloadStart, player.eye()));
    };
    if (reloadPressed && !weapon_.reloading && weapon_.magazine < weapon_.magazineSize && weapon_.reserve > 0) startReload();
    if (!cmd.fire || weapon_.reloading || cooldownTicks_ > 0) return;
    if (weapon_.magazine > 0) {
        shoot(player, rng, events);
        cooldownTicks_ = std::max(1, static_cast<int>(std::round(1.0 / (kRoundsPerSecond * dt_))));
    } else if (weapon_.reserve > 0) {
        startReload();
    } else if (!dryFired_) {
        dryFired_ = true;
        events.push_back(SimEvent::at(SimEventType::DryFire, player.eye()));
    }
}

void Combat::shoot(PlayerState& player, Rng& rng, std::vector<SimEvent>& events) {
    --weapon_.magazine;
    ++weapon_.shotsFired;
    sinceShot_ = 0;
    const Vec3 eye = player.eye(), forward = forwardOf(player.yaw, player.pitch), right = rightOf(player.yaw);
    const Vec3 up = cross(right, forward);
    // Uniform over the cone's disc: radius sqrt(u) of the spread angle.
    const double angle = weapon_.spreadDegrees * kDeg * std::sqrt(rng.uniform01());
    const double phi = 2 * kPi * rng.uniform01();
    const Vec3 dir = normalize(forward * std::cos(angle) + (right * std::cos(phi) + up * std::sin(phi)) * std::sin(angle));
    events.push_back({SimEventType::Shot, eye, {}, dir});

    // Recoil kicks the view; bloom widens the next shot.
    weapon_.recoilDegrees += kRecoilPitch;
    player.pitch = static_cast<float>(std::clamp(player.pitch + kRecoilPitch * kDeg, -1.55, 1.55));
    player.yaw += static_cast<float>(rng.uniform(-kRecoilYaw, kRecoilYaw) * kDeg);
    bloom_ = std::min(kBloomMax, bloom_ + kBloomPerShot);

    // The nearest of the level/props (Bullet) and the targets (analytic boxes) takes the shot.
    const auto hit = physics_.rayCast(eye, eye + dir * kRange);
    const double worldDist = hit ? hit->fraction * kRange : kRange;
    double targetDist = 0;
    Vec3 targetNormal;
    const int target = rayTarget(eye, dir, worldDist, targetDist, targetNormal);
    if (target >= 0) {
        auto& t = targets_[static_cast<std::size_t>(target)];
        const Vec3 at = eye + dir * targetDist;
        events.push_back({SimEventType::Impact, at, targetNormal, dir, 1, target, Surface::Target});
        events.push_back({SimEventType::TargetHit, at, targetNormal, dir, 1, target, Surface::Target});
        ++weapon_.hits;
        score_ += kScoreHit;
        t.health -= kDamage;
        if (t.health <= 0 && t.up) {
            t.up = false;
            score_ += kScoreDown;
            motion_[static_cast<std::size_t>(target)].downTime = 0;
            events.push_back({SimEventType::TargetDown, t.position, {}, dir, 1, target, Surface::Target});
        }
        return;
    }
    if (!hit) return;
    Surface surface = hit->dynamicBody >= 0 ? Surface::Prop : hit->dynamicBody == -2 ? Surface::Grenade : Surface::Level;
    events.push_back({SimEventType::Impact, hit->point, hit->normal, dir, 1, hit->dynamicBody, surface});
    if (hit->dynamicBody >= 0) {
        btRigidBody& body = physics_.dynamicBody(static_cast<std::size_t>(hit->dynamicBody));
        body.activate(true);
        body.applyImpulse(toBt(dir * kImpulse), toBt(hit->point) - body.getCenterOfMassPosition());
        events.push_back({SimEventType::PropHit, hit->point, hit->normal, dir, kImpulse, hit->dynamicBody, Surface::Prop});
    }
}

int Combat::rayTarget(const Vec3& from, const Vec3& dir, double maxDist, double& dist, Vec3& normal) const {
    int best = -1;
    for (std::size_t i = 0; i < targets_.size(); ++i) {
        const auto& t = targets_[i];
        if (!t.up || t.raise < 0.9) continue;  // lying down or still rising: under the bullets
        // Into the board's frame (x across, y up, z through): undo its yaw.
        const double c = std::cos(t.yaw), s = std::sin(t.yaw);
        const Vec3 p = from - t.position;
        const Vec3 o{p.x * c - p.z * s, p.y, p.x * s + p.z * c}, d{dir.x * c - dir.z * s, dir.y, dir.x * s + dir.z * c};
        const double lo[3] = {-t.width / 2, 0, -kTargetThickness / 2}, hi[3] = {t.width / 2, t.height, kTargetThickness / 2};
        const double os[3] = {o.x, o.y, o.z}, ds[3] = {d.x, d.y, d.z};
        double tNear = 0, tFar = maxDist;
        int axis = -1;
        double sign = 1;
        bool miss = false;
        for (int a = 0; a < 3 && !miss; ++a) {
            if (std::abs(ds[a]) < 1e-12) {
                miss = os[a] < lo[a] || os[a] > hi[a];
                continue;
            }
            double t0 = (lo[a] - os[a]) / ds[a], t1 = (hi[a] - os[a]) / ds[a];
            double enterSign = -1;  // entering through the low face: its normal points down the axis
            if (t0 > t1) {
                std::swap(t0, t1);
                enterSign = 1;
            }
            if (t0 > tNear) {
                tNear = t0;
                axis = a;
                sign = enterSign;
            }
            tFar = std::min(tFar, t1);
            miss = tNear > tFar;
        }
        if (miss || axis < 0 || (best >= 0 && tNear >= dist)) continue;
        best = static_cast<int>(i);
        dist = tNear;
        const Vec3 local{axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0};
        normal = {local.x * c + local.z * s, local.y, -local.x * s + local.z * c};  // back to world
    }
    return best;
}

void Combat::stepTargets(std::vector<SimEvent>& events) {
    for (std::size_t i = 0; i < targets_.size(); ++i) {
        auto& t = targets_[i];
        auto& m = motion_[i];
        if (t.moving && m.distance > 0) {
            // Back and forth across the range: a triangle wave along the board's right.
            m.phase = std::fmod(m.phase + m.speed * dt_, 2 * m.distance);
            const double offset = (m.phase < m.distance ? m.phase : 2 * m.distance - m.phase) - m.distance / 2;
            t.position = t.base + rightOf(t.yaw) * offset;
        }
        if (!t.up && (m.downTime += dt_) >= m.reset) {
            t.up = true;
            t.health = kTargetHealth;
            events.push_back({SimEventType::TargetUp, t.position, {}, {}, 1, static_cast<int>(i), Surface::Target});
        }
        const double goal = t.up ? 1.0 : 0.0;
        t.raise = goal > t.raise ? std::min(goal, t.raise + kRaiseSpeed * dt_) : std::max(goal, t.raise - kRaiseSpeed * dt_);
    }
}

void Combat::stepGrenades(const PlayerCommand& cmd, const PlayerState& player, std::vector<SimEvent>& events) {
    // Fuses, bounces.
    for (std::size_t i = 0; i < grenades_.size();) {
        auto& g = grenades_[i];
        const btRigidBody& body = physics_.projectile(g.body);
        const Vec3 v = fromBt(body.getLinearVelocity());
        const Vec3 change = v - g.lastVelocity + Vec3{0, kBodyGravity * dt_, 0};  // what gravity did not do
        if (length(change) > kBounceSpeed)
            events.push_back({SimEventType::GrenadeBounce, fromBt(body.getWorldTransform().getOrigin()), {}, {}, length(change), g.body, Surface::Grenade});
        g.lastVelocity = v;
        g.fuseLeft -= dt_;
        if (g.fuseLeft <= 0) {
            detonate(g.body, events);
            continue;  // detonate() erased it
        }
        ++i;
    }
    // Charge while held, throw on release.
    if (cmd.throwHeld) {
        if (!charging_) charge_ = 0;
        charging_ = true;
        charge_ = std::min(1.0, charge_ + dt_ / kChargeSeconds);
        return;
    }
    if (!charging_) return;
    charging_ = false;
    if (grenades_.size() >= kMaxGrenades) detonate(grenades_.front().body, events);  // the oldest goes early
    const Vec3 eye = player.eye(), forward = forwardOf(player.yaw, player.pitch);
    const Vec3 up = cross(rightOf(player.yaw), forward);
    const Vec3 dir = normalize(forward * std::cos(kThrowLift) + up * std::sin(kThrowLift));
    Vec3 start = eye + forward * kThrowAhead;
    // Facing a wall closely: release it on this side of the wall.
    if (const auto blocked = physics_.rayCast(eye, start + forward * kGrenadeRadius))
        start = eye + forward * std::max(0.0, blocked->fraction * (kThrowAhead + kGrenadeRadius) - 2 * kGrenadeRadius);
    const double speed = kThrowMin + kThrowExtra * charge_;
    const Vec3 velocity = dir * speed + player.velocity;
    const int id = physics_.addProjectile(start, kGrenadeRadius, kGrenadeMass, velocity);
    grenades_.push_back({id, kFuseSeconds, velocity});
    events.push_back({SimEventType::GrenadeThrow, start, {}, dir, speed, id, Surface::Grenade});
    charge_ = 0;
}

void Combat::detonate(int id, std::vector<SimEvent>& events) {
    const auto it = std::find_if(grenades_.begin(), grenades_.end(), [id](const Grenade& g) { return g.body == id; });
    if (it == grenades_.end()) return;
    events.push_back({SimEventType::GrenadeDetonate, fromBt(physics_.projectile(id).getWorldTransform().getOrigin()), {}, {}, 1, id,
                      Surface::Grenade});
    physics_.removeProjectile(id);
    grenades_.erase(it);
}

void Combat::stepMovementCues(const PlayerState& player, const PlayerState& before, std::vector<SimEvent>& events) {
    if (player.onGround && before.onGround) {
        walked_ += std::hypot(player.feet.x - before.feet.x, player.feet.z - before.feet.z);
        if (walked_ >= kStride) {
            walked_ -= kStride;
            events.push_back({SimEventType::Footstep, player.feet, {}, {}, 1, footstep_});
            footstep_ = (footstep_ + 1) % 4;
        }
    }
    if (before.onGround && !player.onGround && player.velocity.y > 1.0) events.push_back(SimEvent::at(SimEventType::Jump, player.feet));
    if (!before.onGround && player.onGround && before.velocity.y < -kLandSpeed)
        events.push_back({SimEventType::Land, player.feet, {}, {}, -before.velocity.y});
}

std::vector<GrenadeState> Combat::grenades() const {
    std::vector<GrenadeState> out;
    for (const auto& g : grenades_) {
        const btTransform& t = physics_.projectile(g.body).getWorldTransform();
        const btQuaternion q = t.getRotation();
        out.push_back({g.body, fromBt(t.getOrigin()), q.x(), q.y(), q.z(), q.w(), kGrenadeRadius, g.fuseLeft,
                       fromBt(physics_.projectile(g.body).getLinearVelocity())});
    }
    return out;
}

void Combat::hash(StateHasher& h) const {
    h.add(static_cast<std::int32_t>(weapon_.magazine));
    h.add(static_cast<std::int32_t>(weapon_.reserve));
    h.add(weapon_.reloading);
    h.add(weapon_.recoilDegrees);
    h.add(weapon_.shotsFired);
    h.add(weapon_.hits);
    h.add(static_cast<std::int32_t>(cooldownTicks_));
    h.add(static_cast<std::int32_t>(reloadTicks_));
    h.add(bloom_);
    h.add(sinceShot_);
    h.add(static_cast<std::int32_t>(score_));
    h.add(charge_);
    for (std::size_t i = 0; i < targets_.size(); ++i) {
        const auto& t = targets_[i];
        for (double v : {t.position.x, t.position.y, t.position.z, t.raise, motion_[i].phase, motion_[i].downTime}) h.add(v);
        h.add(t.up);
        h.add(static_cast<std::int32_t>(t.health));
    }
    for (const auto& g : grenades_) {
        const btRigidBody& b = physics_.projectile(g.body);
        const btVector3 &o = b.getWorldTransform().getOrigin(), &v = b.getLinearVelocity();
        for (btScalar x : {o.x(), o.y(), o.z(), v.x(), v.y(), v.z()}) h.add(static_cast<float>(x));
        h.add(g.fuseLeft);
    }
    h.add(walked_);
    h.add(static_cast<std::int32_t>(footstep_));
}

}  // namespace obscura::sim
