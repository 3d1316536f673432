// Ray-traced ambient-occlusion reference (Embree 3, CPU): the truth the screen-space modes are
// judged against. For each pixel of a pinhole camera it finds the visible surface and shoots
// `rays` cosine-weighted rays into its hemisphere; AO = the share of rays that travel `radius`
// metres without hitting anything — the same quantity the SSAO modes estimate.
// Deterministic: each pixel's rays come from an Rng seeded by the pixel index, so any thread
// count gives the same image.
#pragma once

#include "core/rng.h"
#include "core/triangle_mesh.h"
#include "core/vec3.h"
#include "raytrace/camera_pose.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace obscura::ssao {

using obscura::CameraPose;  // raytrace/camera_pose.h

struct AoImage {
    int width = 0, height = 0;
    std::vector<float> ao;  // row-major, top row first; 1 = unoccluded (and for sky pixels)
    std::vector<std::uint8_t> hit;  // 1 where the pixel sees geometry
};

class AoReference {
public:
    explicit AoReference(const std::vector<TriangleMesh>& meshes);
    ~AoReference();
    AoReference(const AoReference&) = delete;
    AoReference& operator=(const AoReference&) = delete;

    AoImage render(const CameraPose& pose, int width, int height, double radius, int rays, int threads = 2) const;
    // AO at one surface point with its normal (exposed for tests).
    double aoAt(const Vec3& point, const Vec3& normal, double radius, int rays, std::uint64_t seed) const;

    // The pieces render() is made of, for a tracer that refines a view in passes
    // (engine_ext/ao_truth): the same calls in the same order give the same image.
    // The visible surface through pixel (x, y)'s centre and its normal facing the camera; false for sky.
    bool visibleSurface(const CameraPose& pose, int width, int height, int x, int y, Vec3& point, Vec3& normal) const;
    // How many of the next `rays` cosine-weighted rays drawn from `rng` travel `radius` unblocked:
    // aoAt(p, n, r, a + b, seed) == (openRays(p, n, r, a, rng) + openRays(p, n, r, b, rng)) / (a + b)
    // for an rng seeded with `seed`.
    int openRays(const Vec3& point, const Vec3& normal, double radius, int rays, Rng& rng) const;
    // The seed of pixel i's rays (row-major index).
    static std::uint64_t pixelSeed(std::size_t i) { return 0x9e3779b97f4a7c15ULL ^ i; }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace obscura::ssao
