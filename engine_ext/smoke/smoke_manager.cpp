#include "smoke/smoke_manager.h"

#include <algorithm>

#include "smoke/thread_pool.h"

namespace obscura::smoke {

SmokeManager::SmokeManager(std::size_t maxVolumes, const SmokeSettings& settings)
    : maxVolumes_(std::max<std::size_t>(1, maxVolumes)), settings_(settings),
      pool_(std::make_shared<ThreadPool>(settings.threads)) {}

int SmokeManager::spawn(const map::Level& level, const std::vector<TriangleMesh>& meshes, const Vec3& centre) {
    SmokeVolume vol = SmokeVolume::create(level, meshes, centre, settings_, pool_);  // may throw: nothing changed
    while (volumes_.size() >= maxVolumes_) volumes_.erase(volumes_.begin());
    volumes_.push_back({nextId_, std::move(vol)});
    return nextId_++;
}

void SmokeManager::step(double dt) {
    for (auto& e : volumes_) e.volume.step(dt);
    volumes_.erase(std::remove_if(volumes_.begin(), volumes_.end(), [](const Entry& e) { return e.volume.finished(); }),
                   volumes_.end());
}

void SmokeManager::computeTransmittance(const Vec3& towardLight) {
    for (auto& e : volumes_) {
        e.volume.computeTransmittance(towardLight);
        e.volume.computeSkyVisibility();
    }
}

void SmokeManager::setMovingObstacles(const std::vector<MovingObstacle>& obstacles) {
    for (auto& e : volumes_) e.volume.setMovingObstacles(obstacles);
}

void SmokeManager::carve(const Vec3& origin, const Vec3& direction, double length, double radius, double wakeSpeed) {
    for (auto& e : volumes_) e.volume.carve(origin, direction, length, radius, wakeSpeed);
}

void SmokeManager::clear() { volumes_.clear(); }

double SmokeManager::sampleDensity(const Vec3& world) const {
    double sum = 0;
    for (const auto& e : volumes_) sum += e.volume.sampleDensity(world);
    return sum;
}

double SmokeManager::opticalDepth(const Vec3& from, const Vec3& to) const {
    double sum = 0;
    for (const auto& e : volumes_) sum += e.volume.opticalDepth(from, to);
    return sum;
}

}  // namespace obscura::smoke
