#include "smoke/smoke_volume.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "smoke/smoke_volume_impl.h"
#include "smoke/thread_pool.h"
#include "smoke/voxelize.h"

namespace obscura::smoke {

namespace {

constexpr int kMinResolution = 16;   // below this the 16-cell ghost/stencil margins leave no cloud
constexpr int kMaxResolution = 128;  // 128^3 x ~30 float fields = 250 MB: the most a game should hold

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string str(const Vec3& v) {
    std::ostringstream o;
    o << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return o.str();
}

}  // namespace

SmokeVolume::SmokeVolume(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SmokeVolume::SmokeVolume(SmokeVolume&&) noexcept = default;
SmokeVolume& SmokeVolume::operator=(SmokeVolume&&) noexcept = default;
SmokeVolume::~SmokeVolume() = default;

SmokeVolume SmokeVolume::create(const map::Level& level, const std::vector<TriangleMesh>& meshes, const Vec3& centre,
                                const SmokeSettings& settingsIn, std::shared_ptr<ThreadPool> pool) {
    SmokeSettings st = settingsIn;
    if (st.resolution < kMinResolution || st.resolution > kMaxResolution) {
        const int clamped = std::clamp(st.resolution, kMinResolution, kMaxResolution);
        std::cerr << "smoke: resolution " << st.resolution << " is outside [" << kMinResolution << ", "
                  << kMaxResolution << "]; using " << clamped << "\n";
        st.resolution = clamped;
    }
    if (!(st.cellSize > 0) || !std::isfinite(st.cellSize))
        throw std::runtime_error("smoke: cell size must be a positive number of metres, got " + std::to_string(st.cellSize));
    if (!finite(centre)) throw std::runtime_error("smoke: the detonation point is not a finite position");
    if (level.bounds.empty()) throw std::runtime_error("smoke: the level has no brushes to put smoke in");
    const auto& b = level.bounds;
    if (centre.x < b.min.x || centre.y < b.min.y || centre.z < b.min.z || centre.x > b.max.x || centre.y > b.max.y ||
        centre.z > b.max.z)
        throw std::runtime_error("smoke: the detonation point " + str(centre) + " is outside the level bounds " +
                                 str(b.min) + " - " + str(b.max));
    st.pressureIterations = std::max(0, st.pressureIterations);
    st.maxSubsteps = std::max(1, st.maxSubsteps);

    auto impl = std::make_unique<Impl>();
    SmokeState& s = impl->state;
    const int n = st.resolution;
    s.grid.nx = s.grid.ny = s.grid.nz = n;
    s.grid.cellSize = st.cellSize;
    s.grid.origin = centre - Vec3{n * st.cellSize, n * st.cellSize, n * st.cellSize} * 0.5;
    s.centre = centre;
    voxelizeLevel(level, meshes, s.grid, s.voxelSolid);
    for (const auto& brush : level.brushes) {
        if (!brush.solid || brush.mover || centre.x < brush.bounds.min.x || centre.y < brush.bounds.min.y ||
            centre.z < brush.bounds.min.z || centre.x > brush.bounds.max.x || centre.y > brush.bounds.max.y ||
            centre.z > brush.bounds.max.z)
            continue;
        const ConvexHull hull = makeHull(brush);
        bool inside = !hull.planes.empty();
        for (const Plane& pl : hull.planes) inside = inside && dot(pl.normal, centre) < pl.offset - 1e-6;
        if (inside)
            throw std::runtime_error("smoke: the detonation point " + str(centre) + " is inside a solid brush (line " +
                                     std::to_string(brush.pos.line) + " of the map)");
    }
    // The seed cell: the centre's own, or, when conservative voxelisation made that one solid (a
    // grenade resting on a floor or against a wall), the free cell nearest the centre within two
    // cells (ties: the first in x-fastest order).
    const Vec3 cc = s.grid.toCellCoords(centre);
    const int ci = static_cast<int>(std::lround(cc.x)), cj = static_cast<int>(std::lround(cc.y)),
              ck = static_cast<int>(std::lround(cc.z));
    double best = 1e300;
    bool found = false;
    for (int dk = -2; dk <= 2; ++dk)
        for (int dj = -2; dj <= 2; ++dj)
            for (int di = -2; di <= 2; ++di) {
                const int i = ci + di, j = cj + dj, k = ck + dk;
                if (i < 1 || j < 1 || k < 1 || i > n - 2 || j > n - 2 || k > n - 2) continue;
                if (s.voxelSolid[s.grid.index(i, j, k)]) continue;
                const Vec3 off = s.grid.cellCentre(i, j, k) - centre;
                const double dist = dot(off, off);
                if (dist < best) {
                    best = dist;
                    s.startCell = s.grid.index(i, j, k);
                    found = true;
                }
            }
    if (!found)
        throw std::runtime_error("smoke: the detonation point " + str(centre) +
                                 " is inside a solid (brush or mesh) at the grid's resolution");
    initialiseState(s, st);
    impl->settings = st;
    impl->pool = pool ? std::move(pool) : std::make_shared<ThreadPool>(st.threads);
    impl->transmittance.assign(s.grid.cells(), 1.f);
    impl->skyVisibility.assign(s.grid.cells(), 1.f);
    // Prime the flow: a substep of length 0 projects the still air with the emitter's volume
    // source, so the first step's gas already leaves its cells at the expansion's speed (without
    // it the first step's gas stays put and the canister's cells start at 1.4x the gas density).
    substepFast(s, impl->settings, *impl->pool, 0.f);
    s.stats = {};
    return SmokeVolume(std::move(impl));
}

void SmokeVolume::advance(double dt, bool reference) {
    const auto t0 = std::chrono::steady_clock::now();
    Impl& m = *impl_;
    SmokeState& s = m.state;
    if (!(dt > 0) || !std::isfinite(dt)) return;
    dt = std::min(dt, m.settings.maxStep);
    // Substeps from the largest outflow courant number (max is order independent: any thread
    // count agrees, and both paths compute each cell's rate with the same kernel).
    const float rate = reference ? maxOutflowRateReference(s) : maxOutflowRate(s, *m.pool);
    const double cells = rate * dt / std::max(1e-3, m.settings.maxCfl);
    const int substeps = static_cast<int>(std::clamp(std::ceil(cells), 1.0, static_cast<double>(m.settings.maxSubsteps)));
    const float sub = static_cast<float>(dt / substeps);
    s.stats.msAdvect = s.stats.msForces = s.stats.msPressure = s.stats.msProject = 0;
    s.stats.pressureIterationsTotal = 0;
    s.stats.worstRelativeResidual = 0;
    for (int n = 0; n < substeps; ++n) {
        if (reference) substepReference(s, m.settings, sub);
        else substepFast(s, m.settings, *m.pool, sub);
        s.age += sub;
    }
    s.stats.substeps = substeps;
    s.stats.maxSpeed = rate * m.settings.cellSize;
    s.stats.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void SmokeVolume::step(double dt) { advance(dt, false); }
void SmokeVolume::stepReference(double dt) { advance(dt, true); }

void SmokeVolume::setMovingObstacles(const std::vector<MovingObstacle>& obstacles) {
    SmokeState& s = impl_->state;
    const GridInfo& g = s.grid;
    std::vector<DynamicCell> cells;
    for (const MovingObstacle& o : obstacles) {
        if (!finite(o.centre) || !finite(o.velocity)) continue;
        const Vec3 ext = o.shape == MovingObstacle::Shape::Sphere ? Vec3{o.radius, o.radius, o.radius} : o.halfExtents;
        if (!finite(ext)) continue;
        const Vec3 lo = g.toCellCoords(o.centre - ext), hi = g.toCellCoords(o.centre + ext);
        const int i0 = std::max(1, static_cast<int>(std::ceil(std::max(lo.x, -1.0)))),
                  i1 = std::min(g.nx - 2, static_cast<int>(std::floor(std::min(hi.x, 1e6))));
        const int j0 = std::max(1, static_cast<int>(std::ceil(std::max(lo.y, -1.0)))),
                  j1 = std::min(g.ny - 2, static_cast<int>(std::floor(std::min(hi.y, 1e6))));
        const int k0 = std::max(1, static_cast<int>(std::ceil(std::max(lo.z, -1.0)))),
                  k1 = std::min(g.nz - 2, static_cast<int>(std::floor(std::min(hi.z, 1e6))));
        const float vx = static_cast<float>(std::clamp(o.velocity.x, -impl_->settings.maxSpeed, impl_->settings.maxSpeed));
        const float vy = static_cast<float>(std::clamp(o.velocity.y, -impl_->settings.maxSpeed, impl_->settings.maxSpeed));
        const float vz = static_cast<float>(std::clamp(o.velocity.z, -impl_->settings.maxSpeed, impl_->settings.maxSpeed));
        for (int k = k0; k <= k1; ++k)
            for (int j = j0; j <= j1; ++j)
                for (int i = i0; i <= i1; ++i) {
                    const Vec3 p = g.cellCentre(i, j, k) - o.centre;
                    const bool inside = o.shape == MovingObstacle::Shape::Sphere
                                            ? dot(p, p) <= o.radius * o.radius
                                            : std::fabs(p.x) <= ext.x && std::fabs(p.y) <= ext.y && std::fabs(p.z) <= ext.z;
                    const std::size_t c = g.index(i, j, k);
                    if (inside && s.staticClass[c] == kFluid) cells.push_back({c, vx, vy, vz});
                }
    }
    sealMovingObstacles(s, impl_->settings, cells);  // a door closed between two rooms
    // Planes touched by the old or the new set.
    int kMin = g.nz, kMax = -1;
    auto plane = [&](std::size_t c) { return static_cast<int>(c / static_cast<std::size_t>(s.dims.sz)); };
    for (const auto& dc : s.dynamicCells) kMin = std::min(kMin, plane(dc.index)), kMax = std::max(kMax, plane(dc.index));
    for (const auto& dc : cells) kMin = std::min(kMin, plane(dc.index)), kMax = std::max(kMax, plane(dc.index));
    const std::vector<std::uint8_t> before(s.cellClass);  // classes before (for "newly covered")
    s.dynamicCells = std::move(cells);
    if (kMax >= 0) rebuildDerived(s, kMin, kMax);
    // Newly covered cells hand their smoke to their free neighbours; pressure restarts at 0.
    const std::ptrdiff_t off[6] = {-1, 1, -s.dims.sy, s.dims.sy, -s.dims.sz, s.dims.sz};
    for (const auto& dc : s.dynamicCells) {
        const std::size_t c = dc.index;
        s.pressure[c] = 0.f;
        if (before[c] != kFluid) continue;
        int free = 0;
        for (std::ptrdiff_t o : off) free += s.cellClass[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + o)] == kFluid;
        if (free > 0) {
            const float share = s.density[c] / static_cast<float>(free);
            for (std::ptrdiff_t o : off) {
                const std::size_t m = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + o);
                if (s.cellClass[m] == kFluid) s.density[m] += share;
            }
        }
        s.density[c] = 0.f;
        s.temperature[c] = 0.f;
    }
}

void SmokeVolume::carve(const Vec3& origin, const Vec3& direction, double length, double radius, double wakeSpeed) {
    SmokeState& s = impl_->state;
    const GridInfo& g = s.grid;
    if (!finite(origin) || !finite(direction) || !std::isfinite(length) || !std::isfinite(radius) || radius <= 0 ||
        length <= 0 || !std::isfinite(wakeSpeed))
        return;
    const Vec3 dir = normalize(direction);
    if (dot(dir, dir) == 0) return;
    length = std::min(length, 4.0 * g.size().x + 4.0 * g.size().y + 4.0 * g.size().z);  // beyond the box is moot
    const Vec3 end = origin + dir * length;
    map::Aabb box;
    box.extend(origin);
    box.extend(end);
    const Vec3 lo = g.toCellCoords(box.min - Vec3{radius, radius, radius});
    const Vec3 hi = g.toCellCoords(box.max + Vec3{radius, radius, radius});
    auto clampIdx = [](double x, int n) { return static_cast<int>(std::clamp(x, 1.0, static_cast<double>(n - 2))); };
    const int i0 = clampIdx(std::floor(lo.x), g.nx), i1 = clampIdx(std::ceil(hi.x), g.nx);
    const int j0 = clampIdx(std::floor(lo.y), g.ny), j1 = clampIdx(std::ceil(hi.y), g.ny);
    const int k0 = clampIdx(std::floor(lo.z), g.nz), k1 = clampIdx(std::ceil(hi.z), g.nz);
    if (hi.x < 1 || hi.y < 1 || hi.z < 1 || lo.x > g.nx - 2 || lo.y > g.ny - 2 || lo.z > g.nz - 2) return;
    const float wake[3] = {static_cast<float>(dir.x * wakeSpeed), static_cast<float>(dir.y * wakeSpeed),
                           static_cast<float>(dir.z * wakeSpeed)};
    const float vmax = static_cast<float>(impl_->settings.maxSpeed);
    // The tunnel's profile, the fraction of the smoke a point keeps: none within radius / 2, a
    // smoothstep out to the radius. Each cell keeps the profile's average over its volume (4^3
    // samples), not its value at the centre, so the tunnel is round at any offset and angle
    // instead of a staircase of whole cells, and the trilinear ray-march shows a round hole.
    auto keep = [&](const Vec3& p) {
        const double t = std::clamp(dot(p - origin, dir), 0.0, length);
        const double x = obscura::length(p - (origin + dir * t)) / radius;
        const double e = std::clamp(2.0 * x - 1.0, 0.0, 1.0);
        return e * e * (3.0 - 2.0 * e);
    };
    const double h = g.cellSize, halfDiagonal = 0.5 * std::sqrt(3.0) * h;
    std::vector<float>* vel[3] = {&s.u, &s.v, &s.w};
    for (int k = k0; k <= k1; ++k)
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const std::size_t c = g.index(i, j, k);
                if (s.cellClass[c] != kFluid) continue;
                const Vec3 p = g.cellCentre(i, j, k);
                const double t = std::clamp(dot(p - origin, dir), 0.0, length);
                const double dist = obscura::length(p - (origin + dir * t));
                if (dist >= radius + halfDiagonal) continue;  // no part of the cell is in the tunnel
                double kept = 0.0;
                if (dist > 0.5 * radius - halfDiagonal) {
                    for (int sz = 0; sz < 4; ++sz)
                        for (int sy = 0; sy < 4; ++sy)
                            for (int sx = 0; sx < 4; ++sx)
                                kept += keep(p + Vec3{(sx - 1.5) * 0.25 * h, (sy - 1.5) * 0.25 * h, (sz - 1.5) * 0.25 * h});
                    kept /= 64.0;
                }
                s.density[c] *= static_cast<float>(kept);
                // The wake: the air the bullet drags along, as strong as the tunnel is clear.
                const float along = static_cast<float>(1.0 - kept);
                for (int a = 0; a < 3; ++a)
                    if (s.faceMask[a][c])
                        (*vel[a])[c] = kernels::clampf((*vel[a])[c] + wake[a] * along, -vmax, vmax);
            }
}

}  // namespace obscura::smoke
