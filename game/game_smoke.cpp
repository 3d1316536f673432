// See game_smoke.h.
#include "game_smoke.h"

#include "smoke_obstacles.h"
#include "tick_durations.h"

#include <algorithm>
#include <chrono>
#include <thread>

namespace obscura {

namespace {
constexpr std::size_t kMaxVolumes = 4;   // the composite's samplers; the oldest is recycled
constexpr double kCarveRadius = 0.8;     // m: clear within 0.4 m, fading to 0.8
constexpr double kMaxShotRange = 200.0;  // m: the rifle's

smoke::SmokeSettings gridOf(int resolution) {
    smoke::SmokeSettings s;
    const double box = s.resolution * s.cellSize;  // 16 m whatever the resolution
    s.resolution = resolution;
    s.cellSize = box / resolution;
    // The solver's pool leaves a core to the render thread: the step runs beside the frame
    // (smoke_pipeline.h), and with every core its own the pool's threads took the render thread's
    // core at each step's start (2-5 ms on its ticks on 2 cores). The bits do not depend on it.
    s.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()) - 1);
    return s;
}
}  // namespace

GameSmoke::GameSmoke(const map::Level& level, std::vector<TriangleMesh> meshes, const Vec3& towardSun, double tickRate,
                     int resolution)
    : level_(level), towardSun_(towardSun), tickSeconds_(1.0 / tickRate),
      ticksPerStep_(ticksFor(kSmokeStepSeconds, tickRate)), settings_(gridOf(resolution)),
      pipeline_(kMaxVolumes, settings_, level, std::move(meshes)) {
    pipeline_.setLamps(smoke::levelLamps(level), {});
}

void GameSmoke::spawn(const Vec3& where) { pipeline_.spawn(where); }

void GameSmoke::setSignLamps(std::vector<smoke::SmokeLamp> lamps) { pipeline_.setLamps(smoke::levelLamps(level_), std::move(lamps)); }

void GameSmoke::onTick(const std::vector<sim::SimEvent>& events, const sim::Simulation& sim) {
    const auto start = std::chrono::steady_clock::now();
    // A shot carves up to what it hit (its Impact follows it in the same tick), else its range.
    const sim::SimEvent* shot = nullptr;
    auto carve = [this](const sim::SimEvent& s, double length) {
        pipeline_.carve(s.position, s.direction, length, kCarveRadius);
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

    // The smoke's clock runs while there may be smoke (from the first release until a step finds
    // every cloud gone), so a cloud steps every ticksPerStep_ ticks from its release.
    if (pipeline_.mayHoldSmoke() && ++ticks_ % ticksPerStep_ == 0) {
        pipeline_.step(tickSeconds_ * static_cast<double>(ticksPerStep_), smokeObstacles(sim), towardSun_);
        ++version_;
    }
    lastTickMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

smoke::SmokeDump GameSmoke::dump() const {
    smoke::SmokeDump d;
    d.time = seconds();
    d.sigma = settings_.shadowSigma;
    for (const auto& f : frame().volumes) {
        smoke::DumpVolume v;
        v.nx = f.grid.nx, v.ny = f.grid.ny, v.nz = f.grid.nz;
        v.origin = f.grid.origin;
        v.cellSize = f.grid.cellSize;
        v.density.resize(f.fields.size() / 3);
        for (std::size_t i = 0; i < v.density.size(); ++i) v.density[i] = f.fields[3 * i];  // as uploaded
        d.volumes.push_back(std::move(v));
    }
    return d;
}

}  // namespace obscura
