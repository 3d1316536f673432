// See light_reference.h.
#include "light_reference.h"

#include "core/rng.h"
#include "lightbake/bake_scene.h"
#include "map/map_lights.h"
#include "map/quake_light.h"
#include "render/level_light_params.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace obscura::lightref {

using lightbake::detail::BakeScene;

namespace {
// The texel the face list is charted at: the reference reads no lightmap, only the faces.
constexpr double kChartTexel = 4.0;

double luminance(const float* c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

struct Tracer {
    const map::Level& level;
    const lightbake::Atlas atlas;
    const BakeScene scene;
    const render::LightGrid grid;
    const lightbake::BakeSky sky;
    const lightbake::BakeSettings bake;  // its albedo
    Tracer(const map::Level& l)
        : level(l), atlas(lightbake::buildAtlas(l, kChartTexel)), scene(l, atlas), grid(render::buildLightGrid(l)),
          sky(lightbake::bakeSkyOf(l)) {}

    // The first face along (o, d): false for none or sky; `front` false when met from behind.
    bool hit(const Vec3& o, const Vec3& d, Vec3& p, Vec3& n, bool& front) const {
        RayScene::Hit h;
        if (!scene.rays().intersect(o, d, 0.0, scene.far(), h) || h.mesh == BakeScene::kSkyMesh) return false;
        n = atlas.charts[scene.chartOf(h.triangle)].normal;
        front = dot(n, d) < 0;
        p = o + d * h.t + n * lightbake::detail::kSurfaceOffset;
        return true;
    }
    Vec3 direct(const Vec3& p, const Vec3& n, std::uint64_t& rays) const {
        Vec3 e = lightbake::detail::lightsAt(level, grid, scene, p, n, rays);
        const double ndotl = dot(n, sky.sunDirection);
        if (ndotl > 0 && dot(sky.sunColour, sky.sunColour) > 0 && lightbake::detail::sunReaches(scene, sky, p, rays))
            e += sky.sunColour * ndotl;
        return e;
    }
    // One path's estimate of the indirect irradiance at (p, n), `left` bounces to go.
    Vec3 indirect(const Vec3& p, const Vec3& n, int left, Rng& rng, std::uint64_t& rays) const {
        Vec3 s, t;
        const Vec3 up = std::abs(n.y) < 0.9 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
        s = normalize(cross(up, n));
        t = cross(n, s);
        const Vec3 d = lightbake::detail::cosineDirection(0, 0, 1, u(rng), u(rng), s, t, n);
        Vec3 q, nq;
        bool front = false;
        ++rays;
        if (!hit(p, d, q, nq, front)) return d.y >= 0 ? sky.above : sky.below;
        if (!front) return {};
        Vec3 e = direct(q, nq, rays);
        if (left > 0) e += indirect(q, nq, left - 1, rng, rays);
        return e * bake.albedo;
    }
    static double u(Rng& rng) { return (rng.nextU32() >> 8) * (1.0 / 16777216.0); }
};

Irradiance blank(int width, int height) {
    Irradiance out;
    out.width = width;
    out.height = height;
    out.rgb.assign(static_cast<std::size_t>(width) * height * 3, 0.0f);
    out.surface.assign(static_cast<std::size_t>(width) * height, 0);
    return out;
}

template <class F> void eachRow(int height, int threads, const F& f) {
    const int n = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (int k = 0; k < n; ++k)
        pool.emplace_back([&, k] {
            for (int y = k; y < height; y += n) f(y);
        });
    for (auto& t : pool) t.join();
}
}  // namespace

Irradiance pathTraced(const map::Level& level, const CameraPose& pose, int width, int height, const ReferenceSettings& s) {
    const Tracer tracer(level);
    Irradiance out = blank(width, height);
    eachRow(height, s.threads, [&](int y) {
        std::uint64_t rays = 0;
        for (int x = 0; x < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            Vec3 p, n;
            bool front = false;
            if (!tracer.hit(pose.eye, cameraRay(pose, width, height, x + 0.5, y + 0.5), p, n, front)) continue;
            out.surface[i] = 1;
            if (!front) continue;  // the camera inside a brush: nothing lit is seen
            Rng rng(0x9e3779b97f4a7c15ULL * (i + 1), 7);
            Vec3 ind;
            for (int k = 0; k < s.samples; ++k) ind += tracer.indirect(p, n, s.bounces - 1, rng, rays);
            ind = ind / static_cast<double>(std::max(1, s.samples));
            ind = {std::max(ind.x, tracer.sky.floor.x), std::max(ind.y, tracer.sky.floor.y), std::max(ind.z, tracer.sky.floor.z)};
            const Vec3 e = tracer.direct(p, n, rays) + ind;
            out.rgb[i * 3] = static_cast<float>(e.x);
            out.rgb[i * 3 + 1] = static_cast<float>(e.y);
            out.rgb[i * 3 + 2] = static_cast<float>(e.z);
        }
    });
    return out;
}

Irradiance beforeTheBake(const map::Level& level, const CameraPose& pose, int width, int height) {
    const Tracer tracer(level);
    const render::LevelLightingParams old = render::computeLevelLighting(level);
    Irradiance out = blank(width, height);
    eachRow(height, 0, [&](int y) {
        std::uint64_t rays = 0;
        for (int x = 0; x < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            Vec3 p, n;
            bool front = false;
            if (!tracer.hit(pose.eye, cameraRay(pose, width, height, x + 0.5, y + 0.5), p, n, front)) continue;
            out.surface[i] = 1;
            // The lights unshadowed (level.frag's grid loop), the sun wrapped (sun_wrap.glsl) with its shadow.
            Vec3 e, floorLight;
            for (int li : tracer.grid.lightsAt(p)) {
                const map::LevelLight& l = level.lights[li];
                const double v = map::lightAt(l, p, n);
                if (l.formula == map::LightFormula::LocalMinimum) floorLight = {std::max(floorLight.x, l.colour.x * v), std::max(floorLight.y, l.colour.y * v), std::max(floorLight.z, l.colour.z * v)};
                else e += l.colour * v;
            }
            const double wrap = std::max((dot(n, old.sunDirection) + 0.2) / 1.2, 0.0);
            if (wrap > 0 && lightbake::detail::sunReaches(tracer.scene, tracer.sky, p, rays)) e += old.sunColour * wrap;
            e = {std::max({e.x, 0.0, floorLight.x}), std::max({e.y, 0.0, floorLight.y}), std::max({e.z, 0.0, floorLight.z})};
            const double skyward = 0.5 + 0.5 * n.y;
            e += (old.groundAmbient + (old.skyAmbient - old.groundAmbient) * skyward) * map::ambientScaleAt(level.ambientAreas, p);
            out.rgb[i * 3] = static_cast<float>(e.x);
            out.rgb[i * 3 + 1] = static_cast<float>(e.y);
            out.rgb[i * 3 + 2] = static_cast<float>(e.z);
        }
    });
    return out;
}

double rmse(const Irradiance& reference, const std::vector<float>& rgb) {
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < reference.surface.size(); ++i) {
        if (!reference.surface[i]) continue;
        const double d = luminance(&reference.rgb[i * 3]) - luminance(&rgb[i * 3]);
        sum += d * d;
        ++n;
    }
    return n ? std::sqrt(sum / n) : 0.0;
}

}  // namespace obscura::lightref
