// The irradiance volume's bake (bake_scene.h: bakeProbes): each probe gathers probeRays
// cosine-weighted rays about +Y and about -Y; a probe more than kMaxBackFaceShare of whose rays meet
// faces from behind is inside a brush, and takes its darkest valid neighbour's light.
#include "lightbake/bake_scene.h"

#include "core/rng.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace obscura::lightbake::detail {

namespace {
// A probe whose rays meet faces from behind more often than this sits inside solid (or in a
// wall's thickness): its own gather is not light anyone sees.
constexpr double kMaxBackFaceShare = 0.25;
// Passes of the fill that gives probes inside solid their darkest valid neighbour's light (a wall
// up to this many cells thick is filled from both sides).
constexpr int kFillPasses = 4;

double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }
}  // namespace

ProbeGrid bakeProbes(const map::Level& level, const BakeScene& scene, const BakeSky& sky, const BakeSettings& settings,
                     const std::vector<float>& faceLight, const std::function<void(const std::string&)>& progress,
                     std::atomic<std::uint64_t>& rays) {
    ProbeGrid grid;
    if (level.bounds.empty()) return grid;
    const Vec3 extent = level.bounds.max - level.bounds.min;
    double cell = std::max(settings.probeCell, 1e-3);
    auto along = [&](double e) { return static_cast<int>(std::floor(e / cell)) + 2; };  // the far side covered
    while (static_cast<double>(along(extent.x)) * along(extent.y) * along(extent.z) > static_cast<double>(kMaxProbes)) cell *= 1.25;
    grid.cell = cell;
    grid.origin = level.bounds.min;
    grid.nx = along(extent.x);
    grid.ny = along(extent.y);
    grid.nz = along(extent.z);
    const std::size_t n = grid.count();
    grid.up.assign(n * 3, 0.0f);
    grid.down.assign(n * 3, 0.0f);
    std::vector<char> valid(n, 0);

    const int k = std::max(1, static_cast<int>(std::lround(std::sqrt(std::max(1, settings.probeRays)))));
    const int threads = settings.threads > 0 ? settings.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    parallelFor(n, threads, "lightbake: probes", progress, [&](std::size_t index) {
        const int i = static_cast<int>(index % grid.nx), j = static_cast<int>(index / grid.nx % grid.ny),
                  l = static_cast<int>(index / (static_cast<std::size_t>(grid.nx) * grid.ny));
        const Vec3 p = grid.origin + Vec3{double(i), double(j), double(l)} * cell;
        Rng rng(0x2545f4914f6cdd1dULL * (index + 1), 3);
        int back = 0;
        for (int side = 0; side < 2; ++side) {
            const Vec3 nrm{0, side == 0 ? 1.0 : -1.0, 0}, s{1, 0, 0}, t = cross(nrm, s);
            Vec3 sum;
            for (int a = 0; a < k; ++a)
                for (int b = 0; b < k; ++b) {
                    const double r1 = (rng.nextU32() >> 8) * (1.0 / 16777216.0), r2 = (rng.nextU32() >> 8) * (1.0 / 16777216.0);
                    bool backFace = false;
                    sum += scene.incoming(p, cosineDirection(a, b, k, r1, r2, s, t, nrm), sky, settings.albedo, faceLight, backFace);
                    back += backFace ? 1 : 0;
                }
            sum = sum / static_cast<double>(k * k);
            float* out = &(side == 0 ? grid.up : grid.down)[index * 3];
            out[0] = static_cast<float>(std::max(sum.x, sky.floor.x));
            out[1] = static_cast<float>(std::max(sum.y, sky.floor.y));
            out[2] = static_cast<float>(std::max(sum.z, sky.floor.z));
        }
        valid[index] = back <= kMaxBackFaceShare * 2 * k * k ? 1 : 0;
        rays += static_cast<std::uint64_t>(2 * k * k);
    });

    for (int pass = 0; pass < kFillPasses; ++pass) {
        std::vector<char> next = valid;
        for (std::size_t index = 0; index < n; ++index) {
            if (valid[index]) continue;
            const int i = static_cast<int>(index % grid.nx), j = static_cast<int>(index / grid.nx % grid.ny),
                      l = static_cast<int>(index / (static_cast<std::size_t>(grid.nx) * grid.ny));
            const int offsets[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
            double best = 1e300;
            std::size_t from = index;
            for (const auto& o : offsets) {
                const int x = i + o[0], y = j + o[1], z = l + o[2];
                if (x < 0 || y < 0 || z < 0 || x >= grid.nx || y >= grid.ny || z >= grid.nz) continue;
                const std::size_t m = static_cast<std::size_t>(x) + grid.nx * (static_cast<std::size_t>(y) + grid.ny * z);
                if (!valid[m]) continue;
                const double lum = luminance(&grid.up[m * 3]) + luminance(&grid.down[m * 3]);
                if (lum < best) {
                    best = lum;
                    from = m;
                }
            }
            if (from == index) continue;
            std::copy_n(&grid.up[from * 3], 3, &grid.up[index * 3]);
            std::copy_n(&grid.down[from * 3], 3, &grid.down[index * 3]);
            next[index] = 1;
        }
        valid.swap(next);
    }
    // Probes no fill reached (deep inside solid): no light.
    for (std::size_t index = 0; index < n; ++index)
        if (!valid[index])
            for (int c = 0; c < 3; ++c) grid.up[index * 3 + c] = grid.down[index * 3 + c] = 0.0f;
    return grid;
}

}  // namespace obscura::lightbake::detail
