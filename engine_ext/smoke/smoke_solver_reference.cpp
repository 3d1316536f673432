// The scalar reference substep: single-threaded, one field per loop, boundary conditions decided
// by branching on the cell classes, the pressure stencil's neighbour count recomputed per cell.
// Advection, forces and the relaxation solvers share only the per-value maths (smoke_kernels.h)
// with the optimised path; the MultigridCG solve runs the optimised path's grid passes
// (smoke_multigrid_ops.h) as plain scalar loops on one thread. The tests compare the two paths
// (tests/smoke/smoke_solver_test.cpp).
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "smoke/smoke_state.h"

namespace obscura::smoke {
namespace {

#include "smoke/smoke_multigrid_ops.h"
struct SerialRunner {
    template <class Fn>
    void operator()(int k0, int k1, const Fn& fn) const {
        for (int k = k0; k < k1; ++k) fn(k);
    }
};

using kernels::Dims;

template <class Fn>
void forInterior(const Dims& d, int margin, const Fn& fn) {
    for (int k = margin; k < d.nz - margin; ++k)
        for (int j = margin; j < d.ny - margin; ++j)
            for (int i = margin; i < d.nx - margin; ++i) fn(i, j, k, d.sy * j + d.sz * k + i);
}

bool faceOpen(const SmokeState& s, std::ptrdiff_t behind, std::ptrdiff_t c) {
    const std::uint8_t a = s.cellClass[static_cast<std::size_t>(behind)], b = s.cellClass[static_cast<std::size_t>(c)];
    return a != kSolid && b != kSolid && (a == kFluid || b == kFluid);
}

// Flux-form transport of density and temperature: every face's fluxes from the stencil of cells
// along its axis, then each cell from its six faces. A stencil cell outside the array (below the
// first plane, above the last) is replaced by the face's own cell (its value never counts: see
// the optimised path's faceRow).
void transportReference(SmokeState& s, float dt, float decayD, float decayT) {
    const Dims d = s.dims;
    const std::size_t n = s.density.size();
    const float courantPerSpeed = dt / static_cast<float>(s.grid.cellSize);
    std::vector<float> cap(n, 0.f);
    forInterior(d, 1, [&](int, int, int, std::ptrdiff_t c) { cap[static_cast<std::size_t>(c)] = cellOutflowCap(s, static_cast<std::size_t>(c), dt); });
    std::vector<float> flux[2][3];
    for (auto& f : flux)
        for (auto& a : f) a.assign(n, 0.f);
    const std::ptrdiff_t last = static_cast<std::ptrdiff_t>(n) - 1;
    for (int axis = 0; axis < 3; ++axis) {
        const std::ptrdiff_t st = axis == 0 ? 1 : axis == 1 ? d.sy : d.sz;
        const std::vector<float>& vel = axis == 0 ? s.u : axis == 1 ? s.v : s.w;
        const std::vector<std::uint8_t>& mask = s.faceMask[axis];
        // Faces: the lower faces of the interior cells and of the upper ghost layer on this axis.
        const int top[3] = {axis == 0 ? d.nx - 1 : d.nx - 2, axis == 1 ? d.ny - 1 : d.ny - 2, axis == 2 ? d.nz - 1 : d.nz - 2};
        for (int k = 1; k <= top[2]; ++k)
            for (int j = 1; j <= top[1]; ++j)
                for (int i = 1; i <= top[0]; ++i) {
                    const std::ptrdiff_t c = i + d.sy * j + d.sz * k;
                    const std::ptrdiff_t a = c - 2 * st >= 0 ? c - 2 * st : c - st, e = c + st <= last ? c + st : c;
                    const std::size_t ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(c - st),
                                      ud = static_cast<std::size_t>(c), ue = static_cast<std::size_t>(e);
                    float fd = 0.f, ft = 0.f;
                    kernels::faceFluxes(vel[ud] * courantPerSpeed, mask[ud] != 0, mask[ub] != 0, mask[ue] != 0, cap[ub], cap[ud],
                                        s.density[ua], s.density[ub], s.density[ud], s.density[ue], s.temperature[ua],
                                        s.temperature[ub], s.temperature[ud], s.temperature[ue], fd, ft);
                    flux[0][axis][ud] = fd;
                    flux[1][axis][ud] = ft;
                }
    }
    auto update = [&](std::vector<float>& field, const std::vector<float>* f, float decay) {
        std::vector<float> out(field);
        forInterior(d, 1, [&](int, int, int, std::ptrdiff_t c) {
            const std::size_t m = static_cast<std::size_t>(c), x = m + 1, y = m + static_cast<std::size_t>(d.sy),
                              z = m + static_cast<std::size_t>(d.sz);
            out[m] = kernels::fluxUpdate(field[m], f[0][m], f[0][x], f[1][m], f[1][y], f[2][m], f[2][z], decay);
        });
        field = std::move(out);
    };
    update(s.density, flux[0], decayD);
    update(s.temperature, flux[1], decayT);
}

// MacCormack advection of the three velocity components by the velocity before the step.
void advectVelocityReference(SmokeState& s, float dt, float decayV) {
    const Dims d = s.dims;
    const float scale = dt / static_cast<float>(s.grid.cellSize);
    const std::vector<float> u0 = s.u, v0 = s.v, w0 = s.w;  // the velocity every trace uses
    const float *u = u0.data(), *v = v0.data(), *w = w0.data();
    enum Where { UFace, VFace, WFace };
    struct Trace {
        float x, y, z;
    };
    auto disp = [&](Where where, std::ptrdiff_t c) {
        Trace t{};
        switch (where) {
            case UFace: kernels::traceAt<kernels::kAtU>(u, v, w, c, d, scale, t.x, t.y, t.z); break;
            case VFace: kernels::traceAt<kernels::kAtV>(u, v, w, c, d, scale, t.x, t.y, t.z); break;
            default: kernels::traceAt<kernels::kAtW>(u, v, w, c, d, scale, t.x, t.y, t.z); break;
        }
        return t;
    };
    auto advectField = [&](std::vector<float>& field, Where where) {
        std::vector<float> hat(field.size(), 0.f), out(field);  // cells outside the interior keep their values
        forInterior(d, 1, [&](int, int, int, std::ptrdiff_t c) {
            const Trace q = disp(where, c);
            hat[static_cast<std::size_t>(c)] = kernels::advectForward(field.data(), d, c, q.x, q.y, q.z);
        });
        forInterior(d, 1, [&](int, int, int, std::ptrdiff_t c) {
            const Trace q = disp(where, c);
            out[static_cast<std::size_t>(c)] = kernels::advectCorrect(field.data(), hat.data(), d, c, q.x, q.y, q.z) * decayV;
        });
        field = std::move(out);
    };
    advectField(s.u, UFace);
    advectField(s.v, VFace);
    advectField(s.w, WFace);
}

void forcesReference(SmokeState& s, const SmokeSettings& st, float dt) {
    const Dims d = s.dims;
    const float h = static_cast<float>(s.grid.cellSize);
    const float halfInvH = 0.5f / h, epsH = static_cast<float>(st.vorticity) * h;
    const std::size_t n = s.u.size();
    std::vector<float> fx(n, 0.f), fy(n, 0.f), fz(n, 0.f);
    if (st.vorticity != 0) {
        std::vector<float> ox(n, 0.f), oy(n, 0.f), oz(n, 0.f), mag(n, 0.f);
        forInterior(d, 2, [&](int, int, int, std::ptrdiff_t c) {
            const std::size_t m = static_cast<std::size_t>(c);
            kernels::curlAt(s.u.data(), s.v.data(), s.w.data(), c, d, halfInvH, ox[m], oy[m], oz[m]);
        });
        forInterior(d, 2, [&](int, int, int, std::ptrdiff_t c) {
            const std::size_t m = static_cast<std::size_t>(c);
            mag[m] = kernels::magnitude(ox[m], oy[m], oz[m]);
        });
        forInterior(d, 2, [&](int, int, int, std::ptrdiff_t c) {
            const std::size_t m = static_cast<std::size_t>(c);
            kernels::confinementAt(mag.data(), c, d, halfInvH, epsH, ox[m], oy[m], oz[m], fx[m], fy[m], fz[m]);
        });
    }
    const float buoy = static_cast<float>(st.buoyancy), weight = static_cast<float>(st.densityWeight);
    const float vmax = static_cast<float>(st.maxSpeed);
    forInterior(d, 1, [&](int, int, int, std::ptrdiff_t c) {
        const std::size_t m = static_cast<std::size_t>(c);
        s.u[m] = faceOpen(s, c - 1, c) ? kernels::forcedFace(s.u[m], fx[m - 1], fx[m], dt, vmax) : 0.f;
    });
    forInterior(d, 1, [&](int, int, int, std::ptrdiff_t c) {
        const std::size_t m = static_cast<std::size_t>(c), b = m - static_cast<std::size_t>(d.sy);
        if (!faceOpen(s, c - d.sy, c)) {
            s.v[m] = 0.f;
            return;
        }
        const float below = kernels::cellLift(fy[b], s.temperature[b], s.density[b], buoy, weight);
        const float above = kernels::cellLift(fy[m], s.temperature[m], s.density[m], buoy, weight);
        s.v[m] = kernels::forcedFace(s.v[m], below, above, dt, vmax);
    });
    forInterior(d, 1, [&](int, int, int, std::ptrdiff_t c) {
        const std::size_t m = static_cast<std::size_t>(c);
        s.w[m] = faceOpen(s, c - d.sz, c) ? kernels::forcedFace(s.w[m], fz[m - static_cast<std::size_t>(d.sz)], fz[m], dt, vmax) : 0.f;
    });
}

// Neighbour sum over non-solid neighbours in the kernels' order, and their count.
float referenceNeighbours(const SmokeState& s, const std::vector<float>& p, std::ptrdiff_t c, int& count) {
    const Dims& d = s.dims;
    float sum = 0.f;
    count = 0;
    for (std::ptrdiff_t o : {std::ptrdiff_t{-1}, std::ptrdiff_t{1}, -d.sy, d.sy, -d.sz, d.sz}) {
        const std::size_t m = static_cast<std::size_t>(c + o);
        if (s.cellClass[m] == kSolid) continue;
        sum += p[m];
        ++count;
    }
    return sum;
}

void projectReference(SmokeState& s, const SmokeSettings& st, float emitFactor) {
    const Dims d = s.dims;
    const float h = static_cast<float>(s.grid.cellSize), invH = 1.f / h, h2 = h * h;
    float before = 0.f;
    std::fill(s.rhs.begin(), s.rhs.end(), 0.f);
    forInterior(d, 1, [&](int, int, int, std::ptrdiff_t c) {
        const std::size_t m = static_cast<std::size_t>(c);
        if (s.cellClass[m] != kFluid) return;
        const float div = kernels::divergenceAt(s.u.data(), s.v.data(), s.w.data(), c, d, invH);
        s.rhs[m] = kernels::pressureRhs(div, s.source[m] * emitFactor, h2);
        before = std::max(before, std::fabs(div - s.source[m] * emitFactor));
    });

    int iterations = std::max(0, st.pressureIterations);
    auto update = [&](const std::vector<float>& from, std::vector<float>& to, std::ptrdiff_t c) {
        const std::size_t m = static_cast<std::size_t>(c);
        if (s.cellClass[m] != kFluid) return;
        int count = 0;
        const float sum = referenceNeighbours(s, from, c, count);
        to[m] = count > 0 ? kernels::pressureUpdate(sum, s.rhs[m], 1.f / static_cast<float>(count)) : 0.f;
    };
    if (st.pressureSolver == PressureSolver::MultigridCG) iterations = mgops::solve(s, st, SerialRunner{}).iterations;
    else for (int it = 0; it < iterations; ++it) {
        if (st.pressureSolver == PressureSolver::RedBlackGaussSeidel) {
            for (int colour = 0; colour < 2; ++colour)
                forInterior(d, 1, [&](int i, int j, int k, std::ptrdiff_t c) {
                    if (((i + j + k) & 1) == colour) update(s.pressure, s.pressure, c);
                });
        } else {
            std::vector<float> next = s.pressure;
            forInterior(d, 1, [&](int, int, int, std::ptrdiff_t c) { update(s.pressure, next, c); });
            s.pressure = std::move(next);
        }
    }

    float after = 0.f;
    forInterior(d, 1, [&](int, int, int, std::ptrdiff_t c) {
        const std::size_t m = static_cast<std::size_t>(c);
        if (s.cellClass[m] != kFluid) return;
        int count = 0;
        const float sum = referenceNeighbours(s, s.pressure, c, count);
        if (count > 0) after = std::max(after, std::fabs(sum + s.rhs[m] - s.pressure[m] * static_cast<float>(count)) / h2);
    });
    recordProjection(s.stats, before, after, iterations, st.pressureAbsoluteTolerance);

    const std::vector<float>& p = s.pressure;
    forInterior(d, 1, [&](int, int, int, std::ptrdiff_t c) {
        const std::size_t m = static_cast<std::size_t>(c);
        s.u[m] = faceOpen(s, c - 1, c) ? kernels::projectedFace(s.u[m], p[m], p[m - 1], invH) : 0.f;
        s.v[m] = faceOpen(s, c - d.sy, c) ? kernels::projectedFace(s.v[m], p[m], p[m - static_cast<std::size_t>(d.sy)], invH) : 0.f;
        s.w[m] = faceOpen(s, c - d.sz, c) ? kernels::projectedFace(s.w[m], p[m], p[m - static_cast<std::size_t>(d.sz)], invH) : 0.f;
    });
}

}  // namespace

void projectBorderFaces(SmokeState& s) {
    const GridInfo& g = s.grid;
    const auto& d = s.dims;
    const float invH = 1.f / static_cast<float>(g.cellSize);
    const std::vector<float>& p = s.pressure;
    for (int k = 1; k < g.nz - 1; ++k)
        for (int j = 1; j < g.ny - 1; ++j) {
            const std::size_t c = g.index(g.nx - 1, j, k);
            s.u[c] = s.faceMask[0][c] ? kernels::projectedFace(s.u[c], p[c], p[c - 1], invH) : 0.f;
        }
    for (int k = 1; k < g.nz - 1; ++k)
        for (int i = 1; i < g.nx - 1; ++i) {
            const std::size_t c = g.index(i, g.ny - 1, k), b = c - static_cast<std::size_t>(d.sy);
            s.v[c] = s.faceMask[1][c] ? kernels::projectedFace(s.v[c], p[c], p[b], invH) : 0.f;
        }
    for (int j = 1; j < g.ny - 1; ++j)
        for (int i = 1; i < g.nx - 1; ++i) {
            const std::size_t c = g.index(i, j, g.nz - 1), b = c - static_cast<std::size_t>(d.sz);
            s.w[c] = s.faceMask[2][c] ? kernels::projectedFace(s.w[c], p[c], p[b], invH) : 0.f;
        }
}

void substepReference(SmokeState& s, const SmokeSettings& st, float dt) {
    applyEmitter(s, st, dt);
    const float decayD = densityDecay(s, st, dt);
    const float decayT = static_cast<float>(std::exp(-st.temperatureDissipation * dt));
    const float decayV = static_cast<float>(std::exp(-st.velocityDissipation * dt));
    transportReference(s, dt, decayD, decayT);
    advectVelocityReference(s, dt, decayV);
    setBorderFaces(s);  // the curl reads the border faces: give them this step's values
    forcesReference(s, st, dt);
    setBorderFaces(s);
    patchDynamicFaces(s);
    s.projectedSource = s.age < st.emitTime ? 1.f : 0.f;
    projectReference(s, st, s.projectedSource);
    projectBorderFaces(s);
    patchDynamicFaces(s);
}

}  // namespace obscura::smoke
