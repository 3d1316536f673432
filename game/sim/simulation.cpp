// See simulation.h.
#include "sim/simulation.h"

#include "core/state_hash.h"

#include <cmath>

namespace obscura::sim {

namespace {
// 10..1000 Hz: below 10 a tick is a visible stutter and one tick's fall outruns the sub-step
// cap; above 1000 the float sweeps resolve less than a tick's motion.
constexpr double kMinTickRate = 10, kMaxTickRate = 1000;
// Liquid damage as Quake's WaterMove (client.qc): lava 10 x waterlevel every 0.2 s, slime 4 x
// waterlevel every second (the first hit at once); water none (no drowning here).
constexpr int kLavaDamagePerLevel = 10, kSlimeDamagePerLevel = 4;
constexpr double kLavaDamageInterval = 0.2, kSlimeDamageInterval = 1.0;
constexpr int kPlayerHealth = 100;  // Quake's
}  // namespace

Simulation::Simulation(const map::Level& level, const SimConfig& config, const std::vector<TriangleMesh>& modelMeshes)
    : config_(config), rng_(config.seed) {
    if (!(config.tickRate >= kMinTickRate && config.tickRate <= kMaxTickRate))
        throw SimError("simulation: tick rate " + std::to_string(config.tickRate) + " Hz is outside 10..1000");
    const PlayerTuning tuning;
    physics_ = std::make_unique<PhysicsWorld>(kBodyGravity);
    physics_->addLevel(level);
    for (const auto& m : modelMeshes) physics_->addStaticTriangleMesh(m);
    controller_ = std::make_unique<PlayerController>(*physics_, tuning);
    liquids_ = map::LiquidQuery(level);
    controller_->setLiquids(&liquids_);
    combat_ = std::make_unique<Combat>(level, *physics_, config.tickRate);
    keys_ = std::make_unique<EntityKeys>(level, warnings_);
    movers_ = std::make_unique<Movers>(level, *physics_, config.tickRate, *keys_);
    triggers_ = std::make_unique<Triggers>(level, config.tickRate, *keys_);
    pickups_ = std::make_unique<Pickups>(level);
    if (config.overrideStart) {
        startFeet_ = config.startFeet;
        startYaw_ = config.startYaw;
        startPitch_ = config.startPitch;
    } else {
        startFeet_ = level.hasPlayerStart ? level.playerStart : Vec3{};
        startYaw_ = level.hasPlayerStart ? level.playerStartYaw : 0.0;
    }
    player_ = controller_->spawn(startFeet_, startYaw_, startPitch_);
    player_.health = kPlayerHealth;
}

void Simulation::applyLiquidDamage() {
    const bool lava = player_.liquid == map::LiquidKind::Lava, slime = player_.liquid == map::LiquidKind::Slime;
    if ((!lava && !slime) || player_.waterLevel <= 0 || tick_ < nextLiquidDamageTick_) return;
    const int damage = (lava ? kLavaDamagePerLevel : kSlimeDamagePerLevel) * player_.waterLevel;
    const double interval = lava ? kLavaDamageInterval : kSlimeDamageInterval;
    nextLiquidDamageTick_ = tick_ + static_cast<std::uint64_t>(std::llround(interval * config_.tickRate));
    player_.health -= damage;
    liquidDamage_ += damage;
}

void Simulation::respawnIfDead() {
    if (player_.health > 0) return;
    // Dead (slime, lava, a trigger_hurt): back to the start, whole (no death sequence yet).
    ++deaths_;
    player_ = controller_->spawn(startFeet_, startYaw_, startPitch_);
    player_.health = kPlayerHealth;
}

void Simulation::step(const PlayerCommand& cmd) {
    events_.clear();
    const PlayerState before = player_;
    controller_->step(player_, cmd, dt());
    // As Quake orders a frame: the player moves and touches triggers, then the movers push.
    triggers_->step(player_, controller_->tuning().radius, *physics_, *movers_, events_);
    std::vector<int> fired;
    movers_->step(player_, *controller_, fired);
    pickups_->step(player_, controller_->tuning().radius, events_);
    for (int door : movers_->keyDoorsTouched()) {  // door_touch: the key opens it and is used up
        const int need = movers_->keysNeeded(door);
        if (pickups_->holds(need)) {
            pickups_->use(need);
            movers_->unlock(door, fired);
            continue;
        }
        SimEvent ev = SimEvent::at(SimEventType::Message, player_.feet);
        ev.notice = need & kGoldKey && !pickups_->holds(kGoldKey) ? Notice::NeedGoldKey : Notice::NeedSilverKey;
        events_.push_back(ev);
    }
    applyLiquidDamage();
    respawnIfDead();
    physics_->step(dt());
    combat_->step(cmd, player_, before, rng_, events_);
    // Shootable movers hit this tick open (the motion starts next tick).
    for (const SimEvent& e : events_)
        if (e.type == SimEventType::Impact) movers_->shot(e.position, fired);
    triggers_->fire(fired, *movers_);
    triggers_->takeMessages(events_);
    ++tick_;
}

std::vector<Simulation::BodyPose> Simulation::bodyPoses() const {
    std::vector<BodyPose> out;
    for (std::size_t i = 0; i < physics_->dynamicBodyCount(); ++i) {
        const btTransform& t = physics_->dynamicBody(i).getWorldTransform();
        const btQuaternion q = t.getRotation();
        const bool cylinder = physics_->dynamicShape(i) == PhysicsWorld::BodyShape::Cylinder;
        out.push_back({fromBt(t.getOrigin()), q.x(), q.y(), q.z(), q.w(), physics_->dynamicHalfExtents(i),
                       cylinder ? BodyPose::Shape::Cylinder : BodyPose::Shape::Box,
                       fromBt(physics_->dynamicBody(i).getLinearVelocity())});
    }
    return out;
}

std::uint64_t Simulation::stateHash() const {
    StateHasher h;
    h.add(tick_);
    const PlayerState& p = player_;
    for (double v : {p.feet.x, p.feet.y, p.feet.z, p.velocity.x, p.velocity.y, p.velocity.z}) h.add(v);
    h.add(p.yaw);
    h.add(p.pitch);
    h.add(p.onGround);
    h.add(p.crouching);
    h.add(p.height);
    h.add(p.waterLevel);
    h.add(static_cast<int>(p.liquid));
    h.add(p.waterJumpTime);
    h.add(p.health);
    h.add(nextLiquidDamageTick_);
    h.add(liquidDamage_);
    h.add(deaths_);
    for (std::size_t i = 0; i < physics_->dynamicBodyCount(); ++i) {
        const btRigidBody& b = physics_->dynamicBody(i);
        const btTransform& t = b.getWorldTransform();
        const btQuaternion q = t.getRotation();
        const btVector3 &o = t.getOrigin(), &lv = b.getLinearVelocity(), &av = b.getAngularVelocity();
        for (btScalar v : {o.x(), o.y(), o.z(), q.x(), q.y(), q.z(), q.w(), lv.x(), lv.y(), lv.z(), av.x(), av.y(), av.z()})
            h.add(static_cast<float>(v));
    }
    combat_->hash(h);
    movers_->hash(h);
    triggers_->hash(h);
    pickups_->hash(h);
    h.add(rng_.state());
    h.add(rng_.increment());
    return h.value();
}

std::string Simulation::stateHashHex() const { return StateHasher::toHex(stateHash()); }

}  // namespace obscura::sim
