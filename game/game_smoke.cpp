// See game_smoke.h.
#include "game_smoke.h"

#include "smoke/smoke_shared.h"
#include "smoke_obstacles.h"
#include "tick_durations.h"

#include <iostream>

namespace obscura {

namespace {
constexpr std::size_t kMaxVolumes = 4;   // the composite's samplers; the oldest is recycled
constexpr double kCarveRadius = 0.8;     // m: clear within 0.4 m, fading to 0.8
constexpr double kMaxShotRange = 200.0;  // m: the rifle's
}  // namespace

namespace {
smoke::SmokeSettings gridOf(int resolution) {
    smoke::SmokeSettings s;
    const double box = s.resolution * s.cellSize;  // 16 m whatever the resolution
    s.resolution = resolution;
    s.cellSize = box / resolution;
    return s;
}
}  // namespace

GameSmoke::GameSmoke(const map::Level& level, std::vector<TriangleMesh> meshes, const Vec3& towardSun, double tickRate,
                     int resolution)
    : level_(level), meshes_(std::move(meshes)), towardSun_(towardSun), tickSeconds_(1.0 / tickRate),
      ticksPerStep_(ticksFor(kSmokeStepSeconds, tickRate)), manager_(kMaxVolumes, gridOf(resolution)) {}

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

    if (manager_.volumes().empty() || ++ticks_ % ticksPerStep_ != 0) return;
    manager_.setMovingObstacles(smokeObstacles(sim));
    manager_.step(tickSeconds_ * static_cast<double>(ticksPerStep_));
    manager_.computeTransmittance(towardSun_);
    ++version_;
}

smoke::SmokeDump GameSmoke::dump() const {
    smoke::SmokeDump d;
    d.time = seconds();
    d.sigma = manager_.settings().shadowSigma;
    std::vector<float> rgb;
    for (const auto& entry : manager_.volumes()) {
        if (d.volumes.size() == SMOKE_MAX_VOLUMES) break;
        const smoke::GridInfo& g = entry.volume.grid();
        entry.volume.exportRGBFloat(rgb);  // density, transmittance to the sun, sky: as uploaded
        smoke::DumpVolume v;
        v.nx = g.nx, v.ny = g.ny, v.nz = g.nz;
        v.origin = g.origin;
        v.cellSize = g.cellSize;
        v.density.resize(rgb.size() / 3);
        for (std::size_t i = 0; i < v.density.size(); ++i) v.density[i] = rgb[3 * i];
        d.volumes.push_back(std::move(v));
    }
    return d;
}

}  // namespace obscura
