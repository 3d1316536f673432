// SmokeManager: owns up to N smoke volumes (one per grenade) sharing one thread pool; spawning
// past the cap drops the oldest; finished volumes are dropped by step().
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "smoke/smoke_volume.h"

namespace obscura::smoke {

class SmokeManager {
public:
    struct Entry {
        int id;
        SmokeVolume volume;
    };

    // maxVolumes >= 1. settings.threads sizes the shared pool.
    explicit SmokeManager(std::size_t maxVolumes = 4, const SmokeSettings& settings = {});

    // Creates a volume at `centre` (throws std::runtime_error like SmokeVolume::create; the
    // manager is unchanged then). Drops the oldest first when full. Returns the new volume's id.
    int spawn(const map::Level& level, const std::vector<TriangleMesh>& meshes, const Vec3& centre);

    void step(double dt);  // steps every volume, then drops the finished ones
    // Every volume's transmittance towards the light and its sky visibility
    // (SmokeVolume::computeTransmittance, computeSkyVisibility): what the renderer lights it by.
    void computeTransmittance(const Vec3& towardLight);
    void setMovingObstacles(const std::vector<MovingObstacle>& obstacles);
    // Carves every volume the segment passes through.
    void carve(const Vec3& origin, const Vec3& direction, double length, double radius, double wakeSpeed = 3.0);
    void clear();

    double sampleDensity(const Vec3& world) const;                // sum over volumes
    double opticalDepth(const Vec3& from, const Vec3& to) const;  // sum over volumes

    const std::vector<Entry>& volumes() const { return volumes_; }
    std::size_t maxVolumes() const { return maxVolumes_; }
    const SmokeSettings& settings() const { return settings_; }

private:
    std::size_t maxVolumes_;
    SmokeSettings settings_;
    std::shared_ptr<ThreadPool> pool_;
    std::vector<Entry> volumes_;  // oldest first
    int nextId_ = 1;
};

}  // namespace obscura::smoke
