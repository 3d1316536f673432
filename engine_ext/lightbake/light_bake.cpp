// See light_bake.h. Three passes over the atlas, then the probes:
//   1 direct    each texel: the lights in its light-grid cell (render/light_grid.h), each with a
//               shadow ray; the sun's visibility ray.
//   2 indirect  each texel: gatherRays cosine-weighted rays; the sky where they escape or meet
//               sky, the albedo share of pass 1's light (lights + sun) where they meet a face;
//               then secondBounceRays meeting that first bounce (a second bounce: in a closed lit
//               room it is a tenth of the light, and the reference's third adds a few percent more).
//   2b filter   the indirect light averaged over (2 kFilterRadius + 1)^2 texels of the same chart,
//               along s then t, never across a buried texel: light through a small opening reaches
//               a texel by few of its rays, and unfiltered the noise shows as a blotch a texel.
//   3 probes    probe_bake.cpp, from passes 1 + 2.
#include "lightbake/light_bake.h"

#include "lightbake/bake_scene.h"
#include "map/quake_light.h"
#include "render/light_grid.h"
#include "render/level_light_params.h"
#include "core/rng.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace obscura::lightbake {

using detail::BakeScene;

namespace {
// Texels each side the indirect light is averaged over (2: 1.25 m at 0.25 m texels, under the
// scale on which a room's bounce and sky light change; the direct light is never filtered).
constexpr int kFilterRadius = 2;

// An Rng for texel or probe `index` of a pass: the same draws whatever thread runs it.
Rng rngFor(std::size_t index, std::uint64_t pass) { return Rng(0x9e3779b97f4a7c15ULL * (index + 1), pass); }

double jitter(Rng& rng) { return (rng.nextU32() >> 8) * (1.0 / 16777216.0); }

int threadCount(const BakeSettings& s) {
    if (s.threads > 0) return s.threads;
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// The chart a texel of the atlas belongs to (or -1 for padding), for the passes' flat loops.
std::vector<int> texelCharts(const Atlas& atlas) {
    std::vector<int> owner(atlas.texels(), -1);
    for (std::size_t c = 0; c < atlas.charts.size(); ++c) {
        const Chart& ch = atlas.charts[c];
        for (int j = 0; j < ch.h; ++j)
            for (int i = 0; i < ch.w; ++i) owner[static_cast<std::size_t>(ch.y + j) * atlas.width + ch.x + i] = static_cast<int>(c);
    }
    return owner;
}

// Pass 1 at one texel: writes direct (RGBA) and the light it reflects (RGB, lights + sun).
void directAt(const map::Level& level, const render::LightGrid& grid, const BakeScene& scene, const BakeSky& sky,
              const Chart& chart, const Vec3& p, float* direct, float* source, std::uint64_t& rays) {
    const Vec3 sum = detail::lightsAt(level, grid, scene, p, chart.normal, rays);
    double visible = 0;
    const double ndotl = dot(chart.normal, sky.sunDirection);
    if (dot(sky.sunColour, sky.sunColour) > 0 && ndotl > 0)  // sun_share.glsl: Lambert, nothing facing away
        visible = detail::sunReaches(scene, sky, p, rays) ? 1 : 0;
    const Vec3 reflected = sum + sky.sunColour * (std::max(ndotl, 0.0) * visible);
    direct[0] = static_cast<float>(sum.x);
    direct[1] = static_cast<float>(sum.y);
    direct[2] = static_cast<float>(sum.z);
    direct[3] = static_cast<float>(visible);
    source[0] = static_cast<float>(reflected.x);
    source[1] = static_cast<float>(reflected.y);
    source[2] = static_cast<float>(reflected.z);
}
}  // namespace

BakeSky bakeSkyOf(const map::Level& level) {
    const render::LevelLightingParams p = render::computeLevelLighting(level);
    BakeSky sky;
    sky.sunDirection = p.sunDirection;
    sky.sunColour = p.sunColour;
    sky.above = p.dome;
    sky.below = p.domeBelow;
    sky.floor = p.minlight;
    return sky;
}

LightBake bakeLevel(const map::Level& level, const BakeSky& sky, const BakeSettings& settings,
                    const std::function<void(const std::string&)>& progress) {
    const auto start = std::chrono::steady_clock::now();
    LightBake bake;
    std::string note;
    bake.atlas = buildAtlas(level, settings.texel, &note);
    if (!note.empty() && progress) progress(note);
    const Atlas& atlas = bake.atlas;
    const BakeScene scene(level, atlas);
    const render::LightGrid grid = render::buildLightGrid(level);
    const std::vector<int> owner = texelCharts(atlas);
    const int threads = threadCount(settings);
    std::atomic<std::uint64_t> rays{0};

    bake.direct.assign(atlas.texels() * 4, 0.0f);
    bake.indirect.assign(atlas.texels() * 3, 0.0f);
    std::vector<float> source(atlas.texels() * 3, 0.0f);
    std::vector<char> buried(atlas.texels(), 0);  // texels under another brush: dark, no rays
    auto texelOf = [&](std::size_t index, int& i, int& j) -> const Chart* {
        if (owner[index] < 0) return nullptr;
        const Chart& c = atlas.charts[owner[index]];
        i = static_cast<int>(index % atlas.width) - c.x;
        j = static_cast<int>(index / atlas.width) - c.y;
        return &c;
    };

    detail::parallelFor(atlas.texels(), threads, "lightbake: direct", progress, [&](std::size_t index) {
        int i, j;
        const Chart* c = texelOf(index, i, j);
        if (!c) return;
        const Vec3 p = scene.samplePoint(owner[index], i, j);
        if (scene.buried(p, c->ref.brush)) {
            buried[index] = 1;
            return;
        }
        std::uint64_t count = 0;
        directAt(level, grid, scene, sky, *c, p, &bake.direct[index * 4], &source[index * 3], count);
        rays += count;
    });

    // One gather over every texel: `count` rays (rounded to a square) meeting `faceLight` (RGB a
    // texel) through the albedo, and the sky when `withSky`.
    auto gather = [&](int count, const std::vector<float>& faceLight, bool withSky, std::uint64_t pass, const char* phase) {
        std::vector<float> out(atlas.texels() * 3, 0.0f);
        const int k = std::max(1, static_cast<int>(std::lround(std::sqrt(std::max(1, count)))));
        const BakeSky none{sky.sunDirection, {}, {}, {}, {}};
        detail::parallelFor(atlas.texels(), threads, phase, progress, [&](std::size_t index) {
            int i, j;
            const Chart* c = texelOf(index, i, j);
            if (!c || buried[index]) return;
            const Vec3 p = scene.samplePoint(owner[index], i, j);
            Rng rng = rngFor(index, pass);
            Vec3 sum;
            for (int a = 0; a < k; ++a)
                for (int b = 0; b < k; ++b) {
                    const double r1 = jitter(rng), r2 = jitter(rng);
                    bool back = false;
                    sum += scene.incoming(p, detail::cosineDirection(a, b, k, r1, r2, c->s, c->t, c->normal), withSky ? sky : none,
                                          settings.albedo, faceLight, back);
                }
            sum = sum / static_cast<double>(k * k);
            for (int ch = 0; ch < 3; ++ch) out[index * 3 + ch] = static_cast<float>(ch == 0 ? sum.x : ch == 1 ? sum.y : sum.z);
            rays += static_cast<std::uint64_t>(k * k);
        });
        return out;
    };
    // Separable, and neither pass steps over a buried texel: light does not cross the wall that buries them.
    auto filter = [&](std::vector<float>& light) {
        for (const bool alongT : {false, true}) {
            const std::vector<float> raw = light;
            detail::parallelFor(atlas.texels(), threads, "lightbake: filter", progress, [&](std::size_t index) {
                int i, j;
                const Chart* c = texelOf(index, i, j);
                if (!c || buried[index]) return;
                double sum[3] = {0, 0, 0}, weight = 0;
                for (const int step : {-1, 1})
                    for (int k = step < 0 ? 0 : 1; k <= kFilterRadius; ++k) {
                        const int x = alongT ? i : i + step * k, y = alongT ? j + step * k : j;
                        if (x < 0 || y < 0 || x >= c->w || y >= c->h) break;
                        const std::size_t t = static_cast<std::size_t>(c->y + y) * atlas.width + c->x + x;
                        if (buried[t]) break;
                        for (int ch = 0; ch < 3; ++ch) sum[ch] += raw[t * 3 + ch];
                        weight += 1;
                    }
                for (int ch = 0; ch < 3; ++ch) light[index * 3 + ch] = static_cast<float>(sum[ch] / weight);
            });
        }
    };
    auto lap = [&, last = std::chrono::steady_clock::now()]() mutable {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - last).count();
        last = now;
        return s;
    };
    bake.stats.directSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    lap();
    std::vector<float> first = gather(settings.gatherRays, source, true, 2, "lightbake: bounce");
    filter(first);
    bake.stats.bounceSeconds = lap();
    std::vector<float> second = gather(settings.secondBounceRays, first, false, 4, "lightbake: second bounce");
    filter(second);
    bake.stats.bounceSeconds += lap();
    for (std::size_t t = 0; t < atlas.texels(); ++t)
        for (int ch = 0; ch < 3; ++ch) {
            const double floorLight = ch == 0 ? sky.floor.x : ch == 1 ? sky.floor.y : sky.floor.z;
            bake.indirect[t * 3 + ch] = buried[t] ? 0.0f : static_cast<float>(std::max<double>(first[t * 3 + ch] + second[t * 3 + ch], floorLight));
        }

    // The probes see the faces' whole light: what they reflect of the lights and sun, and of the sky and bounce.
    for (std::size_t t = 0; t < atlas.texels(); ++t)
        for (int ch = 0; ch < 3; ++ch) source[t * 3 + ch] += bake.indirect[t * 3 + ch];
    lap();
    bake.probes = detail::bakeProbes(level, scene, sky, settings, source, progress, rays);
    bake.stats.probeSeconds = lap();

    bake.stats.charts = atlas.charts.size();
    bake.stats.buried = static_cast<std::size_t>(std::count(buried.begin(), buried.end(), 1));
    bake.stats.texels = atlas.texels();
    bake.stats.probes = bake.probes.count();
    bake.stats.lights = level.lights.size();
    bake.stats.rays = rays.load();
    bake.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return bake;
}

long chartAt(const LightBake& bake, const map::Level& level, const Vec3& p, const Vec3& n) {
    for (std::size_t c = 0; c < bake.atlas.charts.size(); ++c) {
        const Chart& ch = bake.atlas.charts[c];
        if (dot(ch.normal, n) < 0.999 || std::abs(dot(ch.normal, p) - ch.planeD) > 1e-6) continue;
        const auto& face = level.brushes[ch.ref.brush].faces[ch.ref.face];
        bool inside = true;
        for (std::size_t k = 0; k < face.vertices.size() && inside; ++k) {
            const Vec3 a = face.vertices[k].position, b = face.vertices[(k + 1) % face.vertices.size()].position;
            inside = dot(cross(b - a, p - a), ch.normal) >= -1e-9;
        }
        if (inside) return static_cast<long>(c);
    }
    return -1;
}

void sampleLightmap(const LightBake& bake, std::size_t chart, const Vec3& p, float direct[4], float indirect[3]) {
    bake.atlas.bilinear(bake.direct, 4, bake.atlas.charts[chart], p, direct);
    bake.atlas.bilinear(bake.indirect, 3, bake.atlas.charts[chart], p, indirect);
}

}  // namespace obscura::lightbake
