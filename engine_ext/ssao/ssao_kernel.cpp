// See ssao_kernel.h.
#include "ssao/ssao_kernel.h"

#include "core/rng.h"

#include <algorithm>
#include <cmath>

namespace obscura::ssao {

namespace {
constexpr double kPi = 3.14159265358979323846;

Vec3 randomUnit(Rng& rng) {
    // Uniform on the sphere: z uniform in [-1, 1], azimuth uniform (Archimedes).
    const double z = 2.0 * rng.uniform01d() - 1.0;
    const double phi = 2.0 * kPi * rng.uniform01d();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Vec3 constrain(Vec3 d, KernelShape shape) {
    if (shape == KernelShape::Hemisphere && d.z < 0) d.z = -d.z;
    return normalize(d);
}
}  // namespace

std::vector<Vec3> randomDirections(int count, KernelShape shape, std::uint64_t seed) {
    Rng rng(seed);
    std::vector<Vec3> out;
    out.reserve(static_cast<std::size_t>(std::max(count, 0)));
    for (int i = 0; i < count; ++i) out.push_back(constrain(randomUnit(rng), shape));
    return out;
}

std::vector<Vec3> relaxDirections(std::vector<Vec3> dirs, KernelShape shape, int iterations) {
    const std::size_t n = dirs.size();
    if (n < 2) return dirs;
    // Step: a fraction of the typical spacing on the unit sphere, shrinking as the pattern settles.
    const double spacing = std::sqrt(4.0 * kPi / static_cast<double>(n));
    for (int it = 0; it < iterations; ++it) {
        const double step = 0.1 * spacing * (1.0 - static_cast<double>(it) / iterations);
        std::vector<Vec3> force(n);
        auto repel = [](const Vec3& a, const Vec3& b) {
            Vec3 d = a - b;
            const double l2 = std::max(dot(d, d), 1e-12);
            return d / (l2 * std::sqrt(l2));  // Coulomb: 1/r^2 along the separation
        };
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                if (j != i) force[i] += repel(dirs[i], dirs[j]);
                if (shape == KernelShape::Hemisphere) {
                    // Relax the hemisphere as the upper half of a sphere with every point mirrored
                    // below the rim (its own mirror included): the rim neither attracts nor repels.
                    force[i] += repel(dirs[i], Vec3{dirs[j].x, dirs[j].y, -dirs[j].z});
                }
            }
        for (std::size_t i = 0; i < n; ++i) {
            // Only the tangential part moves a point along the sphere.
            Vec3 f = force[i] - dirs[i] * dot(force[i], dirs[i]);
            const double fl = length(f);
            if (fl > 0) dirs[i] = constrain(dirs[i] + f / fl * step, shape);
        }
    }
    return dirs;
}

std::vector<Vec3> randomiseRadii(std::vector<Vec3> dirs, std::uint64_t seed) {
    const std::size_t n = dirs.size();
    std::vector<double> s(n);
    for (std::size_t i = 0; i < n; ++i) s[i] = (static_cast<double>(i) + 0.5) / static_cast<double>(n);
    Rng rng(seed ^ 0x5eedu);
    for (std::size_t i = n; i > 1; --i) std::swap(s[i - 1], s[rng.below(static_cast<std::uint32_t>(i))]);
    for (std::size_t i = 0; i < n; ++i) dirs[i] *= 0.1 + 0.9 * s[i] * s[i];
    return dirs;
}

std::vector<Vec3> makeKernel(int count, KernelShape shape, std::uint64_t seed) {
    return randomiseRadii(relaxDirections(randomDirections(count, shape, seed), shape), seed);
}

std::vector<Vec3> kernelFor(int samples, int slots, KernelShape shape, std::uint64_t seed) {
    std::vector<Vec3> k = makeKernel(samples, shape, seed);
    k.resize(static_cast<std::size_t>(std::max(slots, samples)), Vec3{0, 0, 0});
    return k;
}

double minPairwiseDistance(const std::vector<Vec3>& dirs) {
    double best = 1e300;
    for (std::size_t i = 0; i < dirs.size(); ++i)
        for (std::size_t j = i + 1; j < dirs.size(); ++j)
            best = std::min(best, length(normalize(dirs[i]) - normalize(dirs[j])));
    return best;
}

double capDiscrepancy(const std::vector<Vec3>& dirs, KernelShape shape, int caps, std::uint64_t seed) {
    if (dirs.empty()) return 1.0;
    Rng rng(seed);
    const double domain = shape == KernelShape::Hemisphere ? 2.0 * kPi : 4.0 * kPi;
    double worst = 0;
    for (int c = 0; c < caps; ++c) {
        const Vec3 axis = constrain(randomUnit(rng), shape);
        const double angle = (10.0 + 80.0 * rng.uniform01d()) * kPi / 180.0;
        const double cosA = std::cos(angle);
        // The cap's area inside the domain, by Monte Carlo on a fixed sample count for hemispheres
        // (a cap near the rim is cut by it); exact for spheres.
        double share;
        if (shape == KernelShape::Sphere) {
            share = 2.0 * kPi * (1.0 - cosA) / domain;
        } else {
            Rng mc(seed + static_cast<std::uint64_t>(c));
            int inside = 0;
            const int samples = 4000;
            for (int k = 0; k < samples; ++k) inside += dot(constrain(randomUnit(mc), shape), axis) >= cosA;
            share = static_cast<double>(inside) / samples;
        }
        int hits = 0;
        for (const auto& d : dirs) hits += dot(normalize(d), axis) >= cosA;
        worst = std::max(worst, std::fabs(static_cast<double>(hits) / static_cast<double>(dirs.size()) - share));
    }
    return worst;
}

}  // namespace obscura::ssao
