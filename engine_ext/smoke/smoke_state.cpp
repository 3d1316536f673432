#include "smoke/smoke_state.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <utility>

namespace obscura::smoke {
namespace {

// The emitter's cells: grown from the seed cell through faces between fluid cells, nearest to the
// emitter centre first (ties: lower index), until there are as many as a free sphere of
// emitterRadius holds (4/3 pi r^3 / h^3, rounded) or the next one is further than three radii.
// In the open that is the sphere; against a wall, a floor or a ceiling it is the same volume
// squeezed to the reachable side, so the gas never starts behind a wall and the amount does not
// depend on where the canister lies (only a space smaller than the sphere gets fewer cells, each
// taking a larger share of the same total).
void chooseEmitterCells(SmokeState& s, const SmokeSettings& st) {
    const GridInfo& g = s.grid;
    // The plume starts emitterLift above the canister, unless that point is not free space the
    // gas reaches (a grenade stuck under a ceiling): then at the seed cell's centre. (From a point
    // inside the ceiling the nearest cells are a thin sheet under it, which reached the grid's
    // border and lost gas there at once.)
    s.emitterCentre = s.centre + Vec3{0, st.emitterLift, 0};
    const Vec3 lifted = g.toCellCoords(s.emitterCentre);
    const int li = static_cast<int>(std::lround(lifted.x)), lj = static_cast<int>(std::lround(lifted.y)),
              lk = static_cast<int>(std::lround(lifted.z));
    if (!g.contains(li, lj, lk) || s.staticClass[g.index(li, lj, lk)] != kFluid) {
        const int si = static_cast<int>(s.startCell % static_cast<std::size_t>(g.nx));
        const int sj = static_cast<int>((s.startCell / static_cast<std::size_t>(g.nx)) % static_cast<std::size_t>(g.ny));
        const int sk = static_cast<int>(s.startCell / (static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.ny)));
        s.emitterCentre = g.cellCentre(si, sj, sk);
    }
    const double h = g.cellSize, r = std::max(0.0, st.emitterRadius);
    const double want = std::round(4.0 / 3.0 * 3.14159265358979323846 * r * r * r / (h * h * h));
    const std::size_t target = static_cast<std::size_t>(std::clamp(want, 1.0, 1e6));
    const double reach2 = std::pow(std::max(3.0 * r, 1.5 * h), 2);
    auto dist2 = [&](std::size_t c) {
        const int i = static_cast<int>(c % static_cast<std::size_t>(g.nx));
        const int j = static_cast<int>((c / static_cast<std::size_t>(g.nx)) % static_cast<std::size_t>(g.ny));
        const int k = static_cast<int>(c / (static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.ny)));
        const Vec3 off = g.cellCentre(i, j, k) - s.emitterCentre;
        return dot(off, off);
    };
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    std::vector<std::uint8_t> queued(g.cells(), 0);
    s.emitterList.clear();
    open.push({dist2(s.startCell), s.startCell});
    queued[s.startCell] = 1;
    const std::ptrdiff_t off[6] = {-1, 1, -s.dims.sy, s.dims.sy, -s.dims.sz, s.dims.sz};
    while (!open.empty() && s.emitterList.size() < target) {
        const auto [d2, c] = open.top();
        open.pop();
        if (d2 > reach2 && !s.emitterList.empty()) break;
        s.emitterList.push_back(c);
        for (std::ptrdiff_t o : off) {
            const std::size_t m = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + o);
            if (queued[m] || s.staticClass[m] != kFluid) continue;
            queued[m] = 1;
            open.push({dist2(m), m});
        }
    }
    s.emitterCells = s.emitterList.size();
}

}  // namespace

namespace {
// The expansion (1/s) per cell: the emitter's cells add emitterRate; a closed region absorbs the
// emission uniformly over its `cells` fluid cells (`inRegion`), so the sources sum to 0.
template <class InRegion>
void makeSources(SmokeState& s, const SmokeSettings& st, InRegion inRegion, std::size_t cells) {
    const double h3 = s.grid.cellSize * s.grid.cellSize * s.grid.cellSize;
    const double sink = s.regionOpen || cells == 0 ? 0.0 : st.emitGasRate / (static_cast<double>(cells) * h3);
    s.source.assign(s.grid.cells(), 0.f);
    for (std::size_t c = 0; c < s.source.size(); ++c)
        if (inRegion(c)) s.source[c] = static_cast<float>(-sink);
    for (std::size_t c : s.emitterList)
        if (inRegion(c)) s.source[c] = static_cast<float>(static_cast<double>(s.emitterRate) - sink);
}
}  // namespace

void initialiseState(SmokeState& s, const SmokeSettings& st) {
    const GridInfo& g = s.grid;
    const std::size_t n = g.cells();
    s.dims = {g.nx, g.ny, g.nz, static_cast<std::ptrdiff_t>(g.nx), static_cast<std::ptrdiff_t>(g.nx) * g.ny};
    s.staticClass.assign(n, kFluid);
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const std::size_t c = g.index(i, j, k);
                const bool ghost = i == 0 || j == 0 || k == 0 || i == g.nx - 1 || j == g.ny - 1 || k == g.nz - 1;
                if (s.voxelSolid[c]) s.staticClass[c] = kSolid;
                else if (ghost) s.staticClass[c] = st.openBorder ? kOpen : kSolid;
            }

    // Seal: fluid cells not 6-connected to the detonation point can never receive smoke; making
    // them solid keeps the pressure problem of the centre's region well posed (and its source
    // compatible when that region is closed).
    const std::size_t start = s.startCell;
    std::vector<std::uint8_t> reached(n, 0);
    std::vector<std::size_t> stack{start};
    reached[start] = 1;
    s.regionOpen = false;
    const std::ptrdiff_t off[6] = {-1, 1, -s.dims.sy, s.dims.sy, -s.dims.sz, s.dims.sz};
    while (!stack.empty()) {
        const std::size_t c = stack.back();
        stack.pop_back();
        for (std::ptrdiff_t o : off) {
            const std::size_t m = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + o);
            if (s.staticClass[m] == kOpen) s.regionOpen = true;
            if (s.staticClass[m] != kFluid || reached[m]) continue;
            reached[m] = 1;
            stack.push_back(m);
        }
    }
    s.fluidCells = 0;
    for (std::size_t c = 0; c < n; ++c) {
        if (s.staticClass[c] == kFluid && !reached[c]) s.staticClass[c] = kSolid;
        s.fluidCells += s.staticClass[c] == kFluid;
    }

    chooseEmitterCells(s, st);
    const double h3 = g.cellSize * g.cellSize * g.cellSize;
    s.emitterRate = static_cast<float>(st.emitGasRate / (static_cast<double>(s.emitterCells) * h3));
    s.staticRegionOpen = s.regionOpen;
    makeSources(s, st, [&](std::size_t c) { return s.staticClass[c] == kFluid; }, s.fluidCells);

    for (auto* f : {&s.density, &s.temperature, &s.u, &s.v, &s.w, &s.pressure, &s.rhs, &s.pressureTmp, &s.diagInv, &s.outflow})
        f->assign(n, 0.f);
    for (auto& f : s.velHat) f.assign(n, 0.f);
    for (auto& f : s.next) f.assign(n, 0.f);
    for (auto& field : s.flux)
        for (auto& f : field) f.assign(n, 0.f);
    for (auto& f : s.omega) f.assign(n, 0.f);
    for (auto& m : s.faceMask) m.assign(n, 0);
    s.planeA.assign(g.nz, 0.f);
    s.planeB.assign(g.nz, 0.f);
    s.rowScratch.assign(SmokeState::kScratchRows * static_cast<std::size_t>(g.nx) * g.nz, 0.f);
    for (int colour = 0; colour < 2; ++colour)
        for (auto* f : {&s.rbPressure[colour], &s.rbRhs[colour], &s.rbDiagInv[colour]})
            f->assign(static_cast<std::size_t>(s.rbWidth()) * g.ny * g.nz, 0.f);
    s.cellClass = s.staticClass;
    s.dynamicCells.clear();
    s.mg.levels.clear();
    rebuildDerived(s, 0, g.nz - 1);
    initialiseMultigrid(s);
}

void rebuildDerived(SmokeState& s, int k0, int k1) {
    const GridInfo& g = s.grid;
    const auto& d = s.dims;
    k0 = std::max(0, k0);
    k1 = std::min(g.nz - 1, k1);
    if (k0 > k1) return;
    const std::size_t b = g.index(0, 0, k0), e = g.index(0, 0, k1) + static_cast<std::size_t>(d.sz);
    std::copy(s.staticClass.begin() + static_cast<std::ptrdiff_t>(b), s.staticClass.begin() + static_cast<std::ptrdiff_t>(e),
              s.cellClass.begin() + static_cast<std::ptrdiff_t>(b));
    for (const DynamicCell& dc : s.dynamicCells)
        if (dc.index >= b && dc.index < e) s.cellClass[dc.index] = kSolid;

    const auto& cls = s.cellClass;
    auto faceOpen = [&](std::size_t a, std::size_t c) {
        return cls[a] != kSolid && cls[c] != kSolid && (cls[a] == kFluid || cls[c] == kFluid);
    };
    const int m0 = std::max(0, k0 - 1), m1 = std::min(g.nz - 1, k1 + 1);
    for (int k = m0; k <= m1; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const std::size_t c = g.index(i, j, k);
                s.faceMask[0][c] = i > 0 && faceOpen(c - 1, c);
                s.faceMask[1][c] = j > 0 && faceOpen(c - static_cast<std::size_t>(d.sy), c);
                s.faceMask[2][c] = k > 0 && faceOpen(c - static_cast<std::size_t>(d.sz), c);
                float inv = 0.f;
                if (cls[c] == kFluid) {  // fluid cells are never on the ghost layer
                    int count = 0;
                    for (std::ptrdiff_t o : {std::ptrdiff_t{-1}, std::ptrdiff_t{1}, -d.sy, d.sy, -d.sz, d.sz})
                        count += cls[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + o)] != kSolid;
                    inv = count > 0 ? 1.f / static_cast<float>(count) : 0.f;
                }
                s.diagInv[c] = inv;
            }
    updateMultigrid(s, m0, m1);
}

float densityDecay(const SmokeState& s, const SmokeSettings& st, float dt) {
    double rate = st.densityDissipation;
    if (st.fadeTime > 0) {
        const double ramp = std::clamp((s.age - (st.lifetime - st.fadeTime)) / st.fadeTime, 0.0, 1.0);
        rate += ramp * st.fadeDissipation;
    }
    return static_cast<float>(std::exp(-rate * dt));
}

void recordProjection(SmokeStats& st, float before, float after, int iterations, double floor) {
    st.divergenceBefore = before;
    st.residual = after;
    st.pressureIterations = iterations;
    st.pressureIterationsTotal += iterations;
    if (before > 0.f && after > floor) st.worstRelativeResidual = std::max(st.worstRelativeResidual, static_cast<double>(after) / before);
}

float cellOutflowCap(const SmokeState& s, std::size_t c, float dt) { return kernels::outflowCapT(cellOutflowRate(s, c), dt); }

float cellOutflowRate(const SmokeState& s, std::size_t c) {
    const std::size_t sy = static_cast<std::size_t>(s.dims.sy), sz = static_cast<std::size_t>(s.dims.sz);
    const auto& m = s.faceMask;
    return kernels::outflowRateT<float, bool>(s.u[c], s.u[c + 1], s.v[c], s.v[c + sy], s.w[c], s.w[c + sz], m[0][c] != 0,
                                              m[0][c + 1] != 0, m[1][c] != 0, m[1][c + sy] != 0, m[2][c] != 0, m[2][c + sz] != 0,
                                              s.cellClass[c] == kFluid, 1.f / static_cast<float>(s.grid.cellSize));
}

float maxOutflowRateReference(const SmokeState& s) {
    const auto& d = s.dims;
    float worst = 0.f;
    for (int k = 1; k < d.nz - 1; ++k)
        for (int j = 1; j < d.ny - 1; ++j)
            for (int i = 1; i < d.nx - 1; ++i) worst = std::max(worst, cellOutflowRate(s, static_cast<std::size_t>(i + d.sy * j + d.sz * k)));
    return worst;
}

void applyEmitter(SmokeState& s, const SmokeSettings& st, float dt) {
    if (s.age >= st.emitTime) return;
    // The gas brings its smoke and heat: per cell, rate x dt of the cell's volume is new gas.
    const float gas = s.emitterRate * dt;
    const float addDensity = static_cast<float>(st.emitSmokeDensity) * gas;
    const float addHeat = static_cast<float>(st.emitTemperature) * gas;
    const float ev[3] = {static_cast<float>(st.emitVelocity.x), static_cast<float>(st.emitVelocity.y),
                         static_cast<float>(st.emitVelocity.z)};
    const bool jet = ev[0] != 0.f || ev[1] != 0.f || ev[2] != 0.f;
    constexpr float kMaxValue = 100.f;  // guard against absurd emit rates (1 is already thick)
    const std::size_t strides[3] = {1, static_cast<std::size_t>(s.dims.sy), static_cast<std::size_t>(s.dims.sz)};
    std::vector<float>* vel[3] = {&s.u, &s.v, &s.w};
    for (std::size_t c : s.emitterList) {
        if (s.cellClass[c] != kFluid) continue;  // a moving obstacle covers it this step
        s.density[c] = std::min(s.density[c] + addDensity, kMaxValue);
        s.temperature[c] = std::min(s.temperature[c] + addHeat, kMaxValue);
        if (!jet) continue;
        for (int a = 0; a < 3; ++a) {
            if (s.faceMask[a][c]) (*vel[a])[c] = ev[a];
            if (s.faceMask[a][c + strides[a]]) (*vel[a])[c + strides[a]] = ev[a];
        }
    }
}

void setBorderFaces(SmokeState& s) {
    // The upper faces of the last interior layer (between it and the ghost layer): zero-gradient
    // outflow where the face is open, else 0. (The lower ones are ordinary interior faces.)
    const GridInfo& g = s.grid;
    const auto& d = s.dims;
    for (int k = 1; k < g.nz - 1; ++k)
        for (int j = 1; j < g.ny - 1; ++j) {
            const std::size_t c = g.index(g.nx - 1, j, k);
            s.u[c] = s.faceMask[0][c] ? s.u[c - 1] : 0.f;
        }
    for (int k = 1; k < g.nz - 1; ++k)
        for (int i = 1; i < g.nx - 1; ++i) {
            const std::size_t c = g.index(i, g.ny - 1, k);
            s.v[c] = s.faceMask[1][c] ? s.v[c - static_cast<std::size_t>(d.sy)] : 0.f;
        }
    for (int j = 1; j < g.ny - 1; ++j)
        for (int i = 1; i < g.nx - 1; ++i) {
            const std::size_t c = g.index(i, j, g.nz - 1);
            s.w[c] = s.faceMask[2][c] ? s.w[c - static_cast<std::size_t>(d.sz)] : 0.f;
        }
}

void patchDynamicFaces(SmokeState& s) {
    const auto& d = s.dims;
    for (const DynamicCell& dc : s.dynamicCells) {
        const std::size_t c = dc.index;
        const std::size_t sy = static_cast<std::size_t>(d.sy), sz = static_cast<std::size_t>(d.sz);
        // A face keeps 0 when its other side is static solid (nothing flows there).
        if (s.staticClass[c - 1] != kSolid) s.u[c] = dc.vx;
        if (s.staticClass[c + 1] != kSolid) s.u[c + 1] = dc.vx;
        if (s.staticClass[c - sy] != kSolid) s.v[c] = dc.vy;
        if (s.staticClass[c + sy] != kSolid) s.v[c + sy] = dc.vy;
        if (s.staticClass[c - sz] != kSolid) s.w[c] = dc.vz;
        if (s.staticClass[c + sz] != kSolid) s.w[c + sz] = dc.vz;
    }
}

}  // namespace obscura::smoke

namespace obscura::smoke {

void sealMovingObstacles(SmokeState& s, const SmokeSettings& st, std::vector<DynamicCell>& cells) {
    const std::size_t n = s.grid.cells();
    std::vector<std::uint8_t> mark(n, 0);  // 1 covered, 2 reached from the centre
    for (const auto& dc : cells) mark[dc.index] = 1;
    bool open = false;
    std::size_t reachedCells = 0;
    if (s.staticClass[s.startCell] == kFluid && mark[s.startCell] == 0) {
        std::vector<std::size_t> stack{s.startCell};
        mark[s.startCell] = 2;
        const std::ptrdiff_t off[6] = {-1, 1, -s.dims.sy, s.dims.sy, -s.dims.sz, s.dims.sz};
        while (!stack.empty()) {
            const std::size_t c = stack.back();
            stack.pop_back();
            ++reachedCells;
            for (std::ptrdiff_t o : off) {
                const std::size_t m = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + o);
                if (s.staticClass[m] == kOpen) open = true;
                if (s.staticClass[m] != kFluid || mark[m] != 0) continue;
                mark[m] = 2;
                stack.push_back(m);
            }
        }
    } else {
        return;  // an obstacle on the centre itself: leave the region as the walls make it
    }
    const std::size_t before = cells.size();
    for (std::size_t c = 0; c < n; ++c)
        if (s.staticClass[c] == kFluid && mark[c] == 0) cells.push_back({c, 0.f, 0.f, 0.f});
    const bool changed = cells.size() != before || open != s.staticRegionOpen;
    if (!changed && !s.sourceResealed) return;  // as initialiseState made it: untouched
    s.regionOpen = open;
    if (changed) {
        makeSources(s, st, [&](std::size_t c) { return mark[c] == 2; }, reachedCells);
    } else {
        s.regionOpen = s.staticRegionOpen;
        makeSources(s, st, [&](std::size_t c) { return s.staticClass[c] == kFluid; }, s.fluidCells);
    }
    s.sourceResealed = changed;
}

}  // namespace obscura::smoke
