// See bake_scene.h.
#include "lightbake/bake_scene.h"

#include "map/quake_light.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace obscura::lightbake::detail {

namespace {
// Metres a cell of the buried() brush grid: a few brushes a cell in a Quake map; at most
// kMaxBrushCells cells (the cell grows on large levels).
constexpr double kBrushCell = 4.0;
constexpr std::size_t kMaxBrushCells = std::size_t(1) << 18;
// How far inside every plane a point must be to count as buried, metres (kSurfaceOffset is 2 cm).
constexpr double kBuriedDepth = 0.001;
constexpr double kPi = 3.14159265358979323846;

// The nearest point to (ps, pt) inside the convex polygon `poly` (s, t pairs, counter-clockwise),
// pulled kEdgeInset inside when it had to move.
void clampInside(const std::vector<double>& poly, double& ps, double& pt) {
    const std::size_t n = poly.size() / 2;
    bool inside = true;
    for (std::size_t k = 0; k < n && inside; ++k) {
        const double ax = poly[2 * k], ay = poly[2 * k + 1];
        const double bx = poly[2 * ((k + 1) % n)], by = poly[2 * ((k + 1) % n) + 1];
        inside = (bx - ax) * (pt - ay) - (by - ay) * (ps - ax) >= 0;
    }
    if (inside) return;
    double best = 1e300, bs = ps, bt = pt, cs = 0, ct = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const double ax = poly[2 * k], ay = poly[2 * k + 1];
        const double bx = poly[2 * ((k + 1) % n)], by = poly[2 * ((k + 1) % n) + 1];
        cs += ax / n;
        ct += ay / n;
        const double ex = bx - ax, ey = by - ay, len2 = ex * ex + ey * ey;
        const double f = len2 > 0 ? std::clamp(((ps - ax) * ex + (pt - ay) * ey) / len2, 0.0, 1.0) : 0.0;
        const double qx = ax + f * ex, qy = ay + f * ey, d2 = (qx - ps) * (qx - ps) + (qy - pt) * (qy - pt);
        if (d2 < best) {
            best = d2;
            bs = qx;
            bt = qy;
        }
    }
    const double dx = cs - bs, dy = ct - bt, dl = std::sqrt(dx * dx + dy * dy);
    const double step = std::min(kEdgeInset, dl * 0.5);
    ps = dl > 0 ? bs + dx / dl * step : bs;
    pt = dl > 0 ? bt + dy / dl * step : bt;
}
}  // namespace

BakeScene::BakeScene(const map::Level& level, const Atlas& atlas) : atlas_(atlas), level_(level) {
    std::vector<TriangleMesh> meshes(2);
    polygon2d_.resize(atlas.charts.size());
    for (std::size_t c = 0; c < atlas.charts.size(); ++c) {
        const Chart& chart = atlas.charts[c];
        const auto& face = level.brushes[chart.ref.brush].faces[chart.ref.face];
        auto& mesh = meshes[kFaceMesh];
        const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
        for (const auto& v : face.vertices) {
            polygon2d_[c].push_back(dot(v.position, chart.s));
            polygon2d_[c].push_back(dot(v.position, chart.t));
        }
        // A fence (a `{` texture) casts no baked shadow: its holes are alpha-tested, and the
        // sun's shadow map draws them; the bake would make a solid shadow of it.
        if (face.fence) continue;
        for (const auto& v : face.vertices) mesh.vertices.push_back(v.position);
        for (std::uint32_t k = 1; k + 1 < face.vertices.size(); ++k) {
            mesh.indices.insert(mesh.indices.end(), {base, base + k, base + k + 1});
            triangleChart_.push_back(c);
        }
    }
    for (const auto& brush : level.brushes) {
        if (brush.mover) continue;
        for (const auto& face : brush.faces) {
            if (!face.sky || face.vertices.size() < 3) continue;
            auto& mesh = meshes[kSkyMesh];
            const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
            for (const auto& v : face.vertices) mesh.vertices.push_back(v.position);
            for (std::uint32_t k = 1; k + 1 < face.vertices.size(); ++k) mesh.indices.insert(mesh.indices.end(), {base, base + k, base + k + 1});
        }
    }
    scene_ = std::make_unique<RayScene>(meshes);
    far_ = level.bounds.empty() ? 1.0 : 2.0 * length(level.bounds.max - level.bounds.min) + 1.0;

    if (level.bounds.empty()) return;
    const Vec3 extent = level.bounds.max - level.bounds.min;
    double cell = kBrushCell;
    auto cells = [&](double e) { return static_cast<int>(std::floor(e / cell)) + 1; };
    while (static_cast<double>(cells(extent.x)) * cells(extent.y) * cells(extent.z) > static_cast<double>(kMaxBrushCells)) cell *= 1.25;
    brushCell_ = cell;
    gridOrigin_ = level.bounds.min;
    gx_ = cells(extent.x);
    gy_ = cells(extent.y);
    gz_ = cells(extent.z);
    brushCells_.resize(static_cast<std::size_t>(gx_) * gy_ * gz_);
    for (std::size_t b = 0; b < level.brushes.size(); ++b) {
        const auto& brush = level.brushes[b];
        if (!brush.solid || !brush.visible || brush.mover || brush.bounds.empty()) continue;
        const Vec3 lo = (brush.bounds.min - gridOrigin_) / cell, hi = (brush.bounds.max - gridOrigin_) / cell;
        for (int z = std::max(0, int(lo.z)); z <= std::min(gz_ - 1, int(hi.z)); ++z)
            for (int y = std::max(0, int(lo.y)); y <= std::min(gy_ - 1, int(hi.y)); ++y)
                for (int x = std::max(0, int(lo.x)); x <= std::min(gx_ - 1, int(hi.x)); ++x)
                    brushCells_[static_cast<std::size_t>(x) + gx_ * (static_cast<std::size_t>(y) + gy_ * z)].push_back(static_cast<int>(b));
    }
}

bool BakeScene::buried(const Vec3& p, int ownBrush) const {
    if (brushCells_.empty()) return false;
    const Vec3 g = (p - gridOrigin_) / brushCell_;
    const int x = int(std::floor(g.x)), y = int(std::floor(g.y)), z = int(std::floor(g.z));
    if (x < 0 || y < 0 || z < 0 || x >= gx_ || y >= gy_ || z >= gz_) return false;
    for (int b : brushCells_[static_cast<std::size_t>(x) + gx_ * (static_cast<std::size_t>(y) + gy_ * z)]) {
        if (b == ownBrush) continue;
        bool inside = true;
        for (const auto& f : level_.brushes[b].faces) {
            if (f.vertices.empty() || dot(f.normal, p - f.vertices[0].position) > -kBuriedDepth) {
                inside = false;
                break;
            }
        }
        if (inside) return true;
    }
    return false;
}

Vec3 BakeScene::samplePoint(std::size_t chart, int i, int j) const {
    const Chart& c = atlas_.charts[chart];
    const Vec3 centre = atlas_.texelCentre(c, i, j);
    double ps = dot(centre, c.s), pt = dot(centre, c.t);
    clampInside(polygon2d_[chart], ps, pt);
    return c.normal * (c.planeD + kSurfaceOffset) + c.s * ps + c.t * pt;
}

Vec3 BakeScene::incoming(const Vec3& p, const Vec3& d, const BakeSky& sky, double albedo, const std::vector<float>& faceLight,
                         bool& backFace) const {
    backFace = false;
    RayScene::Hit hit;
    if (!scene_->intersect(p, d, 0.0, far_, hit) || hit.mesh == kSkyMesh) return d.y >= 0 ? sky.above : sky.below;
    const std::size_t chart = triangleChart_[hit.triangle];
    if (dot(atlas_.charts[chart].normal, d) >= 0) {
        backFace = true;
        return {};
    }
    float light[3];
    atlas_.bilinear(faceLight, 3, atlas_.charts[chart], p + d * hit.t, light);
    return Vec3{light[0], light[1], light[2]} * albedo;
}

Vec3 lightsAt(const map::Level& level, const render::LightGrid& grid, const BakeScene& scene, const Vec3& p, const Vec3& n,
              std::uint64_t& rays) {
    // Shadow rays stop this many metres short of the light: a light against a face is not shadowed by it.
    constexpr double kLightClearance = 0.01;
    Vec3 sum, floorLight;
    for (int li : grid.lightsAt(p)) {
        const map::LevelLight& l = level.lights[li];
        const double e = map::lightAt(l, p, n);
        if (e == 0) continue;
        if (l.formula == map::LightFormula::LocalMinimum) {  // a floor, no shadow (as level.frag)
            floorLight = {std::max(floorLight.x, l.colour.x * e), std::max(floorLight.y, l.colour.y * e), std::max(floorLight.z, l.colour.z * e)};
            continue;
        }
        const Vec3 toLight = l.position - p;
        const double dist = length(toLight);
        ++rays;
        if (dist > kLightClearance && scene.rays().occluded(p, toLight, 0.0, 1.0 - kLightClearance / dist)) continue;
        sum += l.colour * e;
    }
    return {std::max({sum.x, 0.0, floorLight.x}), std::max({sum.y, 0.0, floorLight.y}), std::max({sum.z, 0.0, floorLight.z})};
}

bool sunReaches(const BakeScene& scene, const BakeSky& sky, const Vec3& p, std::uint64_t& rays) {
    RayScene::Hit hit;
    ++rays;
    return !scene.rays().intersect(p, sky.sunDirection, 0.0, scene.far(), hit) || hit.mesh == BakeScene::kSkyMesh;
}

Vec3 cosineDirection(int a, int b, int k, double r1, double r2, const Vec3& s, const Vec3& t, const Vec3& n) {
    const double u1 = (a + r1) / k, u2 = (b + r2) / k;
    const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
    return s * (r * std::cos(phi)) + t * (r * std::sin(phi)) + n * std::sqrt(std::max(0.0, 1.0 - u1));
}

void parallelFor(std::size_t n, int threads, const std::string& phase, const std::function<void(const std::string&)>& progress,
                 const std::function<void(std::size_t)>& f) {
    constexpr std::size_t kChunk = 64;
    std::atomic<std::size_t> next{0}, done{0};
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto lastReport = start;
    auto work = [&](bool reporter) {
        for (;;) {
            const std::size_t b = next.fetch_add(kChunk);
            if (b >= n) return;
            const std::size_t e = std::min(n, b + kChunk);
            for (std::size_t i = b; i < e; ++i) f(i);
            done += e - b;
            if (reporter && progress) {
                const auto now = Clock::now();
                if (now - start > std::chrono::seconds(1) && now - lastReport > std::chrono::seconds(1)) {
                    lastReport = now;
                    progress(phase + " " + std::to_string(100 * done.load() / std::max<std::size_t>(n, 1)) + "%");
                }
            }
        }
    };
    std::vector<std::thread> pool;
    for (int k = 1; k < threads; ++k) pool.emplace_back(work, false);
    work(true);
    for (auto& t : pool) t.join();
}

}  // namespace obscura::lightbake::detail
