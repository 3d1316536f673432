// See ao_reference.h.
#include "ssao/ao_reference.h"

#include "raytrace/ray_scene.h"

#include <cmath>
#include <limits>
#include <thread>

namespace obscura::ssao {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Rays start this far off the surface so they do not hit the triangle they leave (metres).
constexpr float kRayOffset = 1e-3f;
}  // namespace

struct AoReference::Impl {
    explicit Impl(const std::vector<TriangleMesh>& meshes) : scene(meshes) {}
    RayScene scene;
};

AoReference::AoReference(const std::vector<TriangleMesh>& meshes) : impl_(std::make_unique<Impl>(meshes)) {}

AoReference::~AoReference() = default;

double AoReference::aoAt(const Vec3& p, const Vec3& n, double radius, int rays, std::uint64_t seed) const {
    Rng rng(seed);
    const int open = openRays(p, n, radius, rays, rng);
    return rays > 0 ? static_cast<double>(open) / rays : 1.0;
}

int AoReference::openRays(const Vec3& p, const Vec3& n, double radius, int rays, Rng& rng) const {
    // An orthonormal frame around the normal, then cosine-weighted directions (Malley's method).
    const Vec3 a = std::fabs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 t = normalize(cross(a, n)), b = cross(n, t);
    int open = 0;
    for (int i = 0; i < rays; ++i) {
        const double u1 = rng.uniform01d(), u2 = rng.uniform01d();
        const double r = std::sqrt(u1), phi = 2 * kPi * u2;
        const Vec3 d = t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * std::sqrt(std::max(0.0, 1 - u1));
        open += !impl_->scene.occluded(p + n * kRayOffset, d, kRayOffset, static_cast<float>(radius));
    }
    return open;
}

bool AoReference::visibleSurface(const CameraPose& pose, int width, int height, int x, int y, Vec3& p, Vec3& n) const {
    const Vec3 dir = cameraRay(pose, width, height, x + 0.5, y + 0.5);
    double t = 0;
    if (!impl_->scene.intersect(pose.eye, dir, 0, std::numeric_limits<double>::infinity(), t, n)) return false;
    n = normalize(n);
    if (dot(n, dir) > 0) n = -n;  // the side facing the camera
    p = pose.eye + dir * t;
    return true;
}

AoImage AoReference::render(const CameraPose& pose, int width, int height, double radius, int rays, int threads) const {
    AoImage img;
    img.width = width;
    img.height = height;
    img.ao.assign(static_cast<std::size_t>(width) * height, 1.0f);
    img.hit.assign(img.ao.size(), 0);
    auto rowJob = [&](int y0) {
        for (int y = y0; y < height; y += threads)
            for (int x = 0; x < width; ++x) {
                Vec3 p, n;
                if (!visibleSurface(pose, width, height, x, y, p, n)) continue;
                const auto i = static_cast<std::size_t>(y) * width + x;
                img.hit[i] = 1;
                img.ao[i] = static_cast<float>(aoAt(p, n, radius, rays, pixelSeed(i)));
            }
    };
    threads = std::max(1, threads);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(rowJob, t);
    for (auto& th : pool) th.join();
    return img;
}

}  // namespace obscura::ssao
