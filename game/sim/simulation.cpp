// See simulation.h.
#include "sim/simulation.h"

#include "core/state_hash.h"

#include <cstdlib>

namespace obscura::sim {

namespace {
// prop_crate defaults: a 0.75 m wooden crate of 20 kg.
constexpr double kDefaultCrateSize = 0.75;
constexpr double kDefaultCrateMass = 20;
}  // namespace

Simulation::Simulation(const map::Level& level, const SimConfig& config, const std::vector<TriangleMesh>& modelMeshes)
    : config_(config), rng_(config.seed) {
    PlayerTuning tuning;
    physics_ = std::make_unique<PhysicsWorld>(tuning.gravity);
    for (const auto& b : level.brushes)
        if (b.solid) physics_->addStaticHull(b.hullPoints);
    for (const auto& m : modelMeshes) physics_->addStaticTriangleMesh(m);
    for (const auto& e : level.entities) {
        if (e.classname != "prop_crate" || !e.hasOrigin) continue;
        const std::string& sz = e.value("size");
        const std::string& ms = e.value("mass");
        const double size = sz.empty() ? kDefaultCrateSize : std::atof(sz.c_str());
        const double mass = ms.empty() ? kDefaultCrateMass : std::atof(ms.c_str());
        if (!(size > 0.05 && size < 10) || !(mass > 0 && mass < 10000)) continue;  // nonsense: skip the prop
        const double h = size / 2;
        // The entity origin marks the crate's base, so it starts resting on the floor.
        physics_->addDynamicBox(e.origin + Vec3{0, h, 0}, {h, h, h}, mass, e.yaw);
    }
    controller_ = std::make_unique<PlayerController>(*physics_, tuning);
    player_.feet = config.overrideStart ? config.startFeet : level.hasPlayerStart ? level.playerStart : Vec3{};
    player_.yaw = static_cast<float>(config.overrideStart ? config.startYaw : level.playerStartYaw);
    player_.pitch = static_cast<float>(config.overrideStart ? config.startPitch : 0.0);
    player_.height = static_cast<float>(tuning.standHeight);
    player_.eyeBelowTop = static_cast<float>(tuning.eyeBelowTop);
}

void Simulation::step(const PlayerCommand& cmd) {
    controller_->step(player_, cmd, dt());
    physics_->step(dt());
    ++tick_;
}

std::vector<BodyPose> Simulation::bodyPoses() const {
    std::vector<BodyPose> out;
    for (std::size_t i = 0; i < physics_->dynamicBodyCount(); ++i) {
        const btTransform& t = physics_->dynamicBody(i).getWorldTransform();
        const btQuaternion q = t.getRotation();
        out.push_back({fromBt(t.getOrigin()), q.x(), q.y(), q.z(), q.w(), physics_->dynamicHalfExtents(i)});
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
    h.add(static_cast<std::int32_t>(p.airTicks));
    for (std::size_t i = 0; i < physics_->dynamicBodyCount(); ++i) {
        const btRigidBody& b = physics_->dynamicBody(i);
        const btTransform& t = b.getWorldTransform();
        const btQuaternion q = t.getRotation();
        for (btScalar v : {t.getOrigin().x(), t.getOrigin().y(), t.getOrigin().z(), q.x(), q.y(), q.z(), q.w(),
                           b.getLinearVelocity().x(), b.getLinearVelocity().y(), b.getLinearVelocity().z(),
                           b.getAngularVelocity().x(), b.getAngularVelocity().y(), b.getAngularVelocity().z()})
            h.add(static_cast<float>(v));
    }
    h.add(rng_.state());
    h.add(rng_.increment());
    return h.value();
}

std::string Simulation::stateHashHex() const { return StateHasher::toHex(stateHash()); }

}  // namespace obscura::sim
