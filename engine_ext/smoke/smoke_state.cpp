#include "smoke/smoke_state.h"

#include <algorithm>
#include <cmath>

namespace obscura::smoke {

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

    // Emitter cells: fluid cells whose centre is within the sphere (at least the centre's cell).
    s.emitterCentre = s.centre + Vec3{0, st.emitterLift, 0};
    s.source.assign(n, 0.f);
    s.emitterCells = 0;
    for (int k = 1; k < g.nz - 1; ++k)
        for (int j = 1; j < g.ny - 1; ++j)
            for (int i = 1; i < g.nx - 1; ++i) {
                const std::size_t c = g.index(i, j, k);
                if (s.staticClass[c] != kFluid) continue;
                if (length(g.cellCentre(i, j, k) - s.emitterCentre) <= st.emitterRadius) {
                    s.source[c] = 1.f;
                    ++s.emitterCells;
                }
            }
    if (s.emitterCells == 0) {
        s.source[start] = 1.f;
        s.emitterCells = 1;
    }
    // The expansion (1/s) per cell; a closed region absorbs it uniformly (sum of sources = 0).
    const double q = st.emitExpansion;
    const double sink = s.regionOpen ? 0.0 : q * static_cast<double>(s.emitterCells) / static_cast<double>(s.fluidCells);
    for (std::size_t c = 0; c < n; ++c) {
        if (s.staticClass[c] != kFluid) continue;
        s.source[c] = static_cast<float>((s.source[c] != 0.f ? q : 0.0) - sink);
    }

    for (auto* f : {&s.density, &s.temperature, &s.u, &s.v, &s.w, &s.pressure, &s.rhs, &s.pressureTmp, &s.diagInv})
        f->assign(n, 0.f);
    for (auto& f : s.hat) f.assign(n, 0.f);
    for (auto& f : s.next) f.assign(n, 0.f);
    for (auto& f : s.omega) f.assign(n, 0.f);
    for (auto& m : s.faceMask) m.assign(n, 0);
    s.planeA.assign(g.nz, 0.f);
    s.planeB.assign(g.nz, 0.f);
    s.planeSum.assign(g.nz, 0.0);
    s.planeSumAfter.assign(g.nz, 0.0);
    s.rowScratch.assign(SmokeState::kScratchRows * static_cast<std::size_t>(g.nx) * g.nz, 0.f);
    for (int colour = 0; colour < 2; ++colour)
        for (auto* f : {&s.rbPressure[colour], &s.rbRhs[colour], &s.rbDiagInv[colour]})
            f->assign(static_cast<std::size_t>(s.rbWidth()) * g.ny * g.nz, 0.f);
    s.cellClass = s.staticClass;
    s.dynamicCells.clear();
    rebuildDerived(s, 0, g.nz - 1);
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
}

float densityDecay(const SmokeState& s, const SmokeSettings& st, float dt) {
    double rate = st.densityDissipation;
    if (st.fadeTime > 0) {
        const double ramp = std::clamp((s.age - (st.lifetime - st.fadeTime)) / st.fadeTime, 0.0, 1.0);
        rate += ramp * st.fadeDissipation;
    }
    return static_cast<float>(std::exp(-rate * dt));
}

double planeDensity(const std::vector<float>& density, const kernels::Dims& d, int k) {
    double sum = 0;
    for (int j = 1; j < d.ny - 1; ++j) {
        const float* row = density.data() + d.sy * j + d.sz * k;
        for (int i = 1; i < d.nx - 1; ++i) sum += row[i];
    }
    return sum;
}

double borderOutflow(const SmokeState& s, float dt) {
    const GridInfo& g = s.grid;
    const auto& d = s.dims;
    const float perMetre = dt / static_cast<float>(g.cellSize);
    // Fraction of the interior cell leaving through the face (upwind, at most all of it).
    auto out = [&](float outwardSpeed, std::size_t interior) {
        const float f = kernels::clampf(outwardSpeed * perMetre, 0.f, 1.f);
        return static_cast<double>(f * s.density[interior]);
    };
    double sum = 0;
    const std::size_t sy = static_cast<std::size_t>(d.sy), sz = static_cast<std::size_t>(d.sz);
    for (int k = 1; k < g.nz - 1; ++k)
        for (int j = 1; j < g.ny - 1; ++j) {
            const std::size_t lo = g.index(1, j, k), hi = g.index(g.nx - 1, j, k);
            if (s.cellClass[lo - 1] == kOpen) sum += out(-s.u[lo], lo);
            if (s.cellClass[hi] == kOpen) sum += out(s.u[hi], hi - 1);
        }
    for (int k = 1; k < g.nz - 1; ++k)
        for (int i = 1; i < g.nx - 1; ++i) {
            const std::size_t lo = g.index(i, 1, k), hi = g.index(i, g.ny - 1, k);
            if (s.cellClass[lo - sy] == kOpen) sum += out(-s.v[lo], lo);
            if (s.cellClass[hi] == kOpen) sum += out(s.v[hi], hi - sy);
        }
    for (int j = 1; j < g.ny - 1; ++j)
        for (int i = 1; i < g.nx - 1; ++i) {
            const std::size_t lo = g.index(i, j, 1), hi = g.index(i, j, g.nz - 1);
            if (s.cellClass[lo - sz] == kOpen) sum += out(-s.w[lo], lo);
            if (s.cellClass[hi] == kOpen) sum += out(s.w[hi], hi - sz);
        }
    return sum;
}

float massScale(const SmokeSettings& st, double before, double outflow, double after, float decay) {
    if (!st.conserveMass || !(after > 1e-9)) return 1.f;
    const double target = std::max(0.0, before - outflow) * decay;
    // Clamped: a bounded correction per step even if something odd happened upstream.
    return static_cast<float>(std::clamp(target / after, 0.5, 2.0));
}

void applyEmitter(SmokeState& s, const SmokeSettings& st, float dt) {
    if (s.age >= st.emitTime) return;
    const GridInfo& g = s.grid;
    const float add = static_cast<float>(st.emitDensity) * dt;
    const float temp = static_cast<float>(st.emitTemperature);
    const float ev[3] = {static_cast<float>(st.emitVelocity.x), static_cast<float>(st.emitVelocity.y),
                         static_cast<float>(st.emitVelocity.z)};
    const bool jet = ev[0] != 0.f || ev[1] != 0.f || ev[2] != 0.f;
    constexpr float kMaxDensity = 100.f;  // guard against absurd emit rates (1 is already thick)
    // The emitter's cells: fluid cells with a positive source, or the centre's cell (see above).
    // Scan only the sphere's bounding box.
    const Vec3 lo = g.toCellCoords(s.emitterCentre - Vec3{st.emitterRadius, st.emitterRadius, st.emitterRadius});
    const Vec3 hi = g.toCellCoords(s.emitterCentre + Vec3{st.emitterRadius, st.emitterRadius, st.emitterRadius});
    auto emitInto = [&](std::size_t c) {
        if (s.cellClass[c] != kFluid) return;
        s.density[c] = std::min(s.density[c] + add, kMaxDensity);
        s.temperature[c] = std::max(s.temperature[c], temp);
        if (jet) {
            for (int a = 0; a < 3; ++a) {
                std::vector<float>& f = a == 0 ? s.u : a == 1 ? s.v : s.w;
                const std::size_t stride = a == 0 ? 1 : a == 1 ? static_cast<std::size_t>(s.dims.sy)
                                                               : static_cast<std::size_t>(s.dims.sz);
                if (s.faceMask[a][c]) f[c] = ev[a];
                if (s.faceMask[a][c + stride]) f[c + stride] = ev[a];
            }
        }
    };
    bool any = false;
    for (int k = std::max(1, static_cast<int>(std::floor(lo.z))); k <= std::min(g.nz - 2, static_cast<int>(std::ceil(hi.z))); ++k)
        for (int j = std::max(1, static_cast<int>(std::floor(lo.y))); j <= std::min(g.ny - 2, static_cast<int>(std::ceil(hi.y))); ++j)
            for (int i = std::max(1, static_cast<int>(std::floor(lo.x))); i <= std::min(g.nx - 2, static_cast<int>(std::ceil(hi.x))); ++i)
                if (length(g.cellCentre(i, j, k) - s.emitterCentre) <= st.emitterRadius) {
                    emitInto(g.index(i, j, k));
                    any = true;
                }
    if (!any) emitInto(s.startCell);
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
