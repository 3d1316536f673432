// Inside the bake (light_bake.cpp, probe_bake.cpp): the level's baked faces and sky faces in an
// Embree scene, the rays' common arithmetic, and a parallel loop with progress. Plain C++.
#pragma once

#include "lightbake/light_bake.h"
#include "raytrace/ray_scene.h"
#include "render/light_grid.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace obscura::lightbake::detail {

// Metres a sample point sits off its face: above Embree's single-precision error across a 300 m
// level (~0.1 mm) with margin, and below the thinnest gap a level has (a 1-unit brush, 3 cm).
constexpr double kSurfaceOffset = 0.02;
// Metres a texel centre off its face is pulled inside the face's edge: the sample stays on the face.
constexpr double kEdgeInset = 0.01;

class BakeScene {
public:
    BakeScene(const map::Level& level, const Atlas& atlas);
    const RayScene& rays() const { return *scene_; }
    const Atlas& atlas() const { return atlas_; }
    double far() const { return far_; }
    // The chart a triangle of the baked-face mesh belongs to.
    std::size_t chartOf(unsigned triangle) const { return triangleChart_[triangle]; }
    // The point a chart texel's light is computed at: its centre, moved inside the face if it lies
    // beyond an edge, kSurfaceOffset off the face.
    Vec3 samplePoint(std::size_t chart, int i, int j) const;

    // Whether p lies inside a visible solid brush other than `ownBrush` (a face's texel under the
    // brush beside it, never seen): the bake leaves such texels dark and casts no rays from them.
    bool buried(const Vec3& p, int ownBrush) const;

    // What arrives along a ray from p in unit direction d: the sky's irradiance share (above or
    // below) where it escapes or meets a sky face, the `albedo` share of `faceLight` (RGB a texel)
    // where it meets a baked face from the front, 0 from behind (backFace set).
    Vec3 incoming(const Vec3& p, const Vec3& d, const BakeSky& sky, double albedo, const std::vector<float>& faceLight,
                  bool& backFace) const;

    static constexpr unsigned kFaceMesh = 0, kSkyMesh = 1;

private:
    const Atlas& atlas_;
    std::unique_ptr<RayScene> scene_;
    std::vector<std::size_t> triangleChart_;
    std::vector<std::vector<double>> polygon2d_;  // a chart's face as (s, t) pairs, counter-clockwise
    double far_ = 1;
    const map::Level& level_;
    // Solid visible brushes by cell of a coarse grid (kBrushCell), for buried().
    Vec3 gridOrigin_;
    double brushCell_ = 1;
    int gx_ = 1, gy_ = 1, gz_ = 1;
    std::vector<std::vector<int>> brushCells_;
};

// The map's lights at p (normal n) with their shadow rays, in the frame's units: Quake's falloff
// (map/quake_light.h), delay-4 lights as a floor, negative lights subtracting down to 0. `grid`
// lists the lights reaching each cell (render/light_grid.h).
Vec3 lightsAt(const map::Level& level, const render::LightGrid& grid, const BakeScene& scene, const Vec3& p, const Vec3& n,
              std::uint64_t& rays);
// Whether the sun reaches p: its ray escapes the level or meets a sky face.
bool sunReaches(const BakeScene& scene, const BakeSky& sky, const Vec3& p, std::uint64_t& rays);

// Unit direction for stratum (a, b) of k x k with jitter (r1, r2), cosine-weighted about n with
// tangents s, t.
Vec3 cosineDirection(int a, int b, int k, double r1, double r2, const Vec3& s, const Vec3& t, const Vec3& n);

// Runs f(i) for i in [0, n) on `threads` threads (the caller's among them); the caller's thread
// reports "<phase> <percent>%" through `progress` at most once a second once a second has passed.
void parallelFor(std::size_t n, int threads, const std::string& phase, const std::function<void(const std::string&)>& progress,
                 const std::function<void(std::size_t)>& f);

// Fills the probe grid (probe_bake.cpp) from the baked faces' total light (RGB a texel).
ProbeGrid bakeProbes(const map::Level& level, const BakeScene& scene, const BakeSky& sky, const BakeSettings& settings,
                     const std::vector<float>& faceLight, const std::function<void(const std::string&)>& progress,
                     std::atomic<std::uint64_t>& rays);

}  // namespace obscura::lightbake::detail
