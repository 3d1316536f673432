// See smoke_pipeline.h.
#include "smoke/smoke_pipeline.h"

#include "smoke/smoke_lamp_light.h"
#include "smoke/smoke_shared.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <iostream>

namespace obscura::smoke {

namespace {
// Density below which a cell does not count towards the marched box: 1 m of it passes 98.4 % at
// the solver's shadowSigma (4 /m), nothing to see (what the old RG8 texture rounded to 0).
constexpr float kVisibleDensity = 0.004f;

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// The cells of `fields` (exportRGBFloat) holding visible smoke, one cell wider; false if none.
bool occupiedBox(const GridInfo& g, const std::vector<float>& fields, SmokeBox& box) {
    int lo[3] = {g.nx, g.ny, g.nz}, hi[3] = {-1, -1, -1};
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                if (fields[3 * g.index(i, j, k)] > kVisibleDensity) {
                    const int c[3] = {i, j, k};
                    for (int a = 0; a < 3; ++a) {
                        lo[a] = std::min(lo[a], c[a]);
                        hi[a] = std::max(hi[a], c[a]);
                    }
                }
    if (hi[0] < 0) return false;
    const double h = g.cellSize;
    box.min = g.origin + Vec3{lo[0] - 1.0, lo[1] - 1.0, lo[2] - 1.0} * h;
    box.size = Vec3{hi[0] - lo[0] + 3.0, hi[1] - lo[1] + 3.0, hi[2] - lo[2] + 3.0} * h;
    return true;
}
}  // namespace

void exportFrame(const SmokeManager& manager, const std::vector<SmokeLamp>& levelLamps,
                 const std::vector<SmokeLamp>& signLamps, SmokeFrame& out) {
    auto t = Clock::now();
    std::size_t n = 0;
    std::vector<SmokeBox> boxes;
    for (const auto& entry : manager.volumes()) {
        if (n == SMOKE_MAX_VOLUMES) break;
        if (out.volumes.size() <= n) out.volumes.emplace_back();
        SmokeFrameVolume& v = out.volumes[n];
        v.id = entry.id;
        v.grid = entry.volume.grid();
        entry.volume.exportRGBFloat(v.fields);
        if (!occupiedBox(v.grid, v.fields, v.occupied)) continue;  // nothing visible yet (or any more)
        boxes.push_back(v.occupied);
        ++n;
    }
    out.volumes.resize(n);
    out.exportMs = msSince(t);
    t = Clock::now();
    out.lamps = chooseLamps(boxes, levelLamps, signLamps);
    // Only the marched volumes' maps: the first volumes of the manager among them.
    std::size_t v = 0;
    for (const auto& entry : manager.volumes()) {
        if (v == out.volumes.size()) break;
        if (entry.id != out.volumes[v].id) continue;
        SmokeFrameVolume& fv = out.volumes[v];
        if (out.lamps.shadowed.empty()) fv.lamps.clear();
        else entry.volume.exportLampTransmittance(out.lamps.shadowed, fv.lamps);
        lampLight(fv.grid, fv.occupied, out.lamps.bound, out.lamps.shadowedLevelLamps, fv.lamps, fv.light);
        ++v;
    }
    out.lampMs = msSince(t);
}

SmokePipeline::SmokePipeline(std::size_t maxVolumes, const SmokeSettings& settings, const map::Level& level,
                             std::vector<TriangleMesh> meshes)
    : level_(level), meshes_(std::move(meshes)), worker_([this, maxVolumes, settings] { workerLoop(maxVolumes, settings); }) {}

SmokePipeline::~SmokePipeline() {
    {
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [this] { return !busy_; });
        stop_ = true;
    }
    wake_.notify_one();
    worker_.join();
}

void SmokePipeline::setLamps(std::vector<SmokeLamp> level, std::vector<SmokeLamp> signs) {
    wait();
    levelLamps_ = std::move(level);
    signLamps_ = std::move(signs);
}

void SmokePipeline::spawn(const Vec3& where) {
    pending_.push_back({Command::Kind::Spawn, where, {}, 0, 0});
    maybeLive_ = true;
}

void SmokePipeline::carve(const Vec3& origin, const Vec3& direction, double length, double radius) {
    if (!maybeLive_) return;  // nothing a shot could cross (a carve of no volume does nothing)
    pending_.push_back({Command::Kind::Carve, origin, direction, length, radius});
}

void SmokePipeline::step(double dt, std::vector<MovingObstacle> obstacles, const Vec3& towardSun) {
    wait();
    std::swap(front_, back_);  // the step before, now complete, is what the renderer draws
    bool spawns = false;
    for (const Command& c : pending_) spawns = spawns || c.kind == Command::Kind::Spawn;
    maybeLive_ = spawns || !manager_->volumes().empty();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        job_.commands.swap(pending_);
        job_.version = ++issued_;
        job_.dt = dt;
        job_.obstacles = std::move(obstacles);
        job_.towardSun = towardSun;
        busy_ = true;
    }
    pending_.clear();
    wake_.notify_one();
}

const SmokeManager& SmokePipeline::settled() {
    wait();
    return *manager_;
}

void SmokePipeline::wait() {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return !busy_; });
}

void SmokePipeline::workerLoop(std::size_t maxVolumes, const SmokeSettings& settings) {
    std::unique_lock<std::mutex> lock(mutex_);
    manager_ = std::make_unique<SmokeManager>(maxVolumes, settings);
    busy_ = false;  // the constructor's wait for the manager
    done_.notify_all();
    for (;;) {
        wake_.wait(lock, [this] { return busy_ || stop_; });
        if (stop_) return;
        lock.unlock();
        run(job_);  // job_ and back_ are the worker's while busy_
        lock.lock();
        busy_ = false;
        done_.notify_all();
    }
}

void SmokePipeline::run(const Job& job) {
    auto t = Clock::now();
    for (const Command& c : job.commands) {
        if (c.kind == Command::Kind::Carve) {
            manager_->carve(c.a, c.b, c.length, c.radius);
            continue;
        }
        try {
            manager_->spawn(level_, meshes_, c.a);
        } catch (const std::exception& e) {
            std::cerr << "smoke: no smoke at (" << c.a.x << ", " << c.a.y << ", " << c.a.z << "): " << e.what() << "\n";
        }
    }
    SmokeFrame& f = back_;
    f.version = job.version;
    f.commandMs = msSince(t);
    f.stepMs = f.lightMs = f.exportMs = f.lampMs = 0;
    t = Clock::now();
    if (!manager_->volumes().empty()) {
        manager_->setMovingObstacles(job.obstacles);
        manager_->step(job.dt);
        f.stepMs = msSince(t);
        t = Clock::now();
        manager_->computeTransmittance(job.towardSun);
        f.lightMs = msSince(t);
    }
    exportFrame(*manager_, levelLamps_, signLamps_, f);
}

}  // namespace obscura::smoke
