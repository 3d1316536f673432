// See game_smoke.h.
#include "app/game_smoke.h"

#include "smoke_obstacles.h"


#include <iostream>

namespace obscura {

namespace {
// The smoke steps every third tick (20 Hz at 60): a 64^3 step costs ~6.5 ms on two cores (plus
// ~2.6 ms for the self-shadow and the texture data), four grenades four times that, and the
// cloud moves well under a cell per 50 ms, so the ray-march shows no stepping.
constexpr long kTicksPerStep = 3;
constexpr std::size_t kMaxVolumes = 4;   // the composite's samplers; the oldest is recycled
constexpr double kCarveRadius = 0.8;     // m: clear within 0.4 m, fading to 0.8
constexpr double kMaxShotRange = 200.0;  // m: the rifle's
}  // namespace

GameSmoke::GameSmoke(const map::Level& level, std::vector<TriangleMesh> meshes, const Vec3& towardSun, double tickSeconds)
    : level_(level), meshes_(std::move(meshes)), towardSun_(towardSun), tickSeconds_(tickSeconds), manager_(kMaxVolumes) {}

bool GameSmoke::spawn(const Vec3& where) {
    try {
        manager_.spawn(level_, meshes_, where);
        return true;
    } catch (const std::exception& e) {
        std::cerr << "smoke: no smoke at (" << where.x << ", " << where.y << ", " << where.z << "): " << e.what() << "\n";
        return false;
    }
}

void GameSmoke::onTick(const std::vector<sim::SimEvent>& events, const sim::Simulation& sim) {
    // A shot carves up to what it hit (its Impact follows it in the same tick), else its range.
    const sim::SimEvent* shot = nullptr;
    auto carve = [this](const sim::SimEvent& s, double length) {
        manager_.carve(s.position, s.direction, length, kCarveRadius);
    };
    for (const auto& e : events) {
        if (e.type == sim::SimEventType::GrenadeDetonate) spawn(e.position);
        if (e.type == sim::SimEventType::Shot) {
            if (shot) carve(*shot, kMaxShotRange);
            shot = &e;
        } else if (e.type == sim::SimEventType::Impact && shot) {
            carve(*shot, length(e.position - shot->position));
            shot = nullptr;
        }
    }
    if (shot) carve(*shot, kMaxShotRange);

    if (manager_.volumes().empty() || ++ticks_ % kTicksPerStep != 0) return;
    manager_.setMovingObstacles(smokeObstacles(sim));
    manager_.step(tickSeconds_ * kTicksPerStep);
    manager_.computeTransmittance(towardSun_);
    dirty_ = true;
}

void GameSmoke::render() {
    render_.update(manager_, dirty_, static_cast<float>(static_cast<double>(ticks_) * tickSeconds_));
    dirty_ = false;
}

}  // namespace obscura
