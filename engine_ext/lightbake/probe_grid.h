// The bake's irradiance volume: a regular grid of probes over the level's box, each holding the
// indirect irradiance (sky seen + bounce) a surface would receive there facing up and facing down.
// A point's ambient for normal n is mix(down, up, 0.5 + 0.5 n.y), trilinear between probes.
// Probes inside solid brushes (most of their rays hit back faces) take their darkest valid
// neighbour's light, so light never leaks through a wall into a sealed room. Plain C++.
#pragma once

#include "core/vec3.h"

#include <cstddef>
#include <vector>

namespace obscura::lightbake {

// Probes a level may have: 2^17 (4 MiB of floats); the cell grows on larger levels.
constexpr std::size_t kMaxProbes = std::size_t(1) << 17;

struct ProbeGrid {
    Vec3 origin;       // the first probe's position (the low corner), metres
    double cell = 1;   // metres between probes
    int nx = 0, ny = 0, nz = 0;
    std::vector<float> up, down;  // RGB a probe, x fastest
    std::size_t count() const { return static_cast<std::size_t>(nx) * ny * nz; }
    // The trilinear irradiance at p for a surface facing up and facing down (0 outside the grid's box).
    void sample(const Vec3& p, Vec3& irradianceUp, Vec3& irradianceDown) const;
};

}  // namespace obscura::lightbake
