// The optimised substep: z-slabs on the thread pool, fused passes (all five fields advected in one
// sweep, forces and boundary conditions in one), branch-free boundary handling through the
// precomputed face masks and diagInv, x-contiguous inner loops. Every value is computed by the
// same kernel (smoke_kernels.h) as in the reference path; reductions go through per-z-plane
// partials combined in plane order, so the thread count never changes a bit of the result.
#include <algorithm>
#include <cmath>
#include <utility>

#include "smoke/smoke_state.h"
#include "smoke/thread_pool.h"

namespace obscura::smoke {
namespace {

using kernels::Dims;

template <class Fn>
void forPlanes(ThreadPool& pool, int k0, int k1, const Fn& fn) {  // planes [k0, k1)
    pool.parallelFor(k1 - k0, [&](int b, int e) {
        for (int k = k0 + b; k < k0 + e; ++k) fn(k);
    });
}

void advect(SmokeState& s, const SmokeSettings& st, ThreadPool& pool, float dt, float decayD, float decayT, float decayV) {
    const Dims d = s.dims;
    const float scale = dt / static_cast<float>(s.grid.cellSize);
    const float* F[5] = {s.density.data(), s.temperature.data(), s.u.data(), s.v.data(), s.w.data()};
    float* H[5] = {s.hat[0].data(), s.hat[1].data(), s.hat[2].data(), s.hat[3].data(), s.hat[4].data()};
    float* N[5] = {s.next[0].data(), s.next[1].data(), s.next[2].data(), s.next[3].data(), s.next[4].data()};
    const float *u = F[2], *v = F[3], *w = F[4];
    const std::uint8_t* cls = s.cellClass.data();

    const double outflow = st.conserveMass ? borderOutflow(s, dt) : 0.0;
    // Pass 1: semi-Lagrangian forward step of all five fields (+ this plane's density total).
    forPlanes(pool, 1, d.nz - 1, [&](int k) {
        s.planeSum[static_cast<std::size_t>(k)] = planeDensity(s.density, d, k);
        for (int j = 1; j < d.ny - 1; ++j) {
            const std::ptrdiff_t row = d.sy * j + d.sz * k;
            for (int i = 1; i < d.nx - 1; ++i) {
                const std::ptrdiff_t c = row + i;
                const kernels::Disp qc = kernels::dispAtCell(u, v, w, c, d, scale);
                H[0][c] = kernels::advectForward(F[0], d, i, j, k, qc);
                H[1][c] = kernels::advectForward(F[1], d, i, j, k, qc);
                H[2][c] = kernels::advectForward(F[2], d, i, j, k, kernels::dispAtU(u, v, w, c, d, scale));
                H[3][c] = kernels::advectForward(F[3], d, i, j, k, kernels::dispAtV(u, v, w, c, d, scale));
                H[4][c] = kernels::advectForward(F[4], d, i, j, k, kernels::dispAtW(u, v, w, c, d, scale));
            }
        }
    });
    // Pass 2: MacCormack correction + clamp, dissipation, no smoke in solid cells.
    forPlanes(pool, 1, d.nz - 1, [&](int k) {
        for (int j = 1; j < d.ny - 1; ++j) {
            const std::ptrdiff_t row = d.sy * j + d.sz * k;
            for (int i = 1; i < d.nx - 1; ++i) {
                const std::ptrdiff_t c = row + i;
                const float fluid = cls[c] == kFluid ? 1.f : 0.f;
                const kernels::Disp qc = kernels::dispAtCell(u, v, w, c, d, scale);
                N[0][c] = kernels::advectCorrect(F[0], H[0], d, c, i, j, k, qc) * decayD * fluid;
                N[1][c] = kernels::advectCorrect(F[1], H[1], d, c, i, j, k, qc) * decayT * fluid;
                N[2][c] = kernels::advectCorrect(F[2], H[2], d, c, i, j, k, kernels::dispAtU(u, v, w, c, d, scale)) * decayV;
                N[3][c] = kernels::advectCorrect(F[3], H[3], d, c, i, j, k, kernels::dispAtV(u, v, w, c, d, scale)) * decayV;
                N[4][c] = kernels::advectCorrect(F[4], H[4], d, c, i, j, k, kernels::dispAtW(u, v, w, c, d, scale)) * decayV;
            }
        }
        s.planeSumAfter[static_cast<std::size_t>(k)] = planeDensity(s.next[0], d, k);
    });
    double before = 0, after = 0;
    for (int k = 1; k < d.nz - 1; ++k) before += s.planeSum[static_cast<std::size_t>(k)];
    for (int k = 1; k < d.nz - 1; ++k) after += s.planeSumAfter[static_cast<std::size_t>(k)];
    const float massFactor = massScale(st, before, outflow, after, decayD);
    if (massFactor != 1.f)
        forPlanes(pool, 1, d.nz - 1, [&](int k) {
            float* row = N[0] + d.sz * k;
            for (std::ptrdiff_t c = d.sy; c < d.sz - d.sy; ++c) row[c] *= massFactor;
        });
    std::swap(s.density, s.next[0]);
    std::swap(s.temperature, s.next[1]);
    std::swap(s.u, s.next[2]);
    std::swap(s.v, s.next[3]);
    std::swap(s.w, s.next[4]);
}

void forces(SmokeState& s, const SmokeSettings& st, ThreadPool& pool, float dt) {
    const Dims d = s.dims;
    const float h = static_cast<float>(s.grid.cellSize);
    const float halfInvH = 0.5f / h, epsH = static_cast<float>(st.vorticity) * h;
    float *ox = s.omega[0].data(), *oy = s.omega[1].data(), *oz = s.omega[2].data(), *mag = s.omega[3].data();
    float *u = s.u.data(), *v = s.v.data(), *w = s.w.data();
    if (st.vorticity != 0) {
        forPlanes(pool, 2, d.nz - 2, [&](int k) {
            for (int j = 2; j < d.ny - 2; ++j) {
                const std::ptrdiff_t row = d.sy * j + d.sz * k;
                for (int i = 2; i < d.nx - 2; ++i) {
                    const std::ptrdiff_t c = row + i;
                    kernels::curlAt(u, v, w, c, d, halfInvH, ox[c], oy[c], oz[c]);
                    mag[c] = kernels::magnitude(ox[c], oy[c], oz[c]);
                }
            }
        });
        // The force overwrites omega in place: each cell reads only its own omega and |omega| around.
        forPlanes(pool, 2, d.nz - 2, [&](int k) {
            for (int j = 2; j < d.ny - 2; ++j) {
                const std::ptrdiff_t row = d.sy * j + d.sz * k;
                for (int i = 2; i < d.nx - 2; ++i) {
                    const std::ptrdiff_t c = row + i;
                    kernels::confinementAt(mag, c, d, halfInvH, epsH, ox[c], oy[c], oz[c], ox[c], oy[c], oz[c]);
                }
            }
        });
    }
    const float buoy = static_cast<float>(st.buoyancy), weight = static_cast<float>(st.densityWeight);
    const float vmax = static_cast<float>(st.maxSpeed);
    const float *T = s.temperature.data(), *D = s.density.data();
    const std::uint8_t *mu = s.faceMask[0].data(), *mv = s.faceMask[1].data(), *mw = s.faceMask[2].data();
    forPlanes(pool, 1, d.nz - 1, [&](int k) {
        for (int j = 1; j < d.ny - 1; ++j) {
            const std::ptrdiff_t row = d.sy * j + d.sz * k;
            for (int i = 1; i < d.nx - 1; ++i) {
                const std::ptrdiff_t c = row + i, b = c - d.sy;
                const float fu = kernels::forcedFace(u[c], ox[c - 1], ox[c], dt, vmax);
                const float fv = kernels::forcedFace(v[c], kernels::cellLift(oy[b], T[b], D[b], buoy, weight),
                                                     kernels::cellLift(oy[c], T[c], D[c], buoy, weight), dt, vmax);
                const float fw = kernels::forcedFace(w[c], oz[c - d.sz], oz[c], dt, vmax);
                u[c] = mu[c] ? fu : 0.f;
                v[c] = mv[c] ? fv : 0.f;
                w[c] = mw[c] ? fw : 0.f;
            }
        }
    });
}

void project(SmokeState& s, const SmokeSettings& st, ThreadPool& pool, float emitFactor) {
    const Dims d = s.dims;
    const float h = static_cast<float>(s.grid.cellSize), invH = 1.f / h, h2 = h * h;
    const float *u = s.u.data(), *v = s.v.data(), *w = s.w.data(), *src = s.source.data(), *dinv = s.diagInv.data();
    const std::uint8_t* cls = s.cellClass.data();
    float* rhs = s.rhs.data();
    float* planeA = s.planeA.data();
    forPlanes(pool, 1, d.nz - 1, [&](int k) {
        float maxDiv = 0.f;
        for (int j = 1; j < d.ny - 1; ++j) {
            const std::ptrdiff_t row = d.sy * j + d.sz * k;
            for (int i = 1; i < d.nx - 1; ++i) {
                const std::ptrdiff_t c = row + i;
                const float div = kernels::divergenceAt(u, v, w, c, d, invH);
                const bool fluid = cls[c] == kFluid;
                const float a = fluid ? std::fabs(div - src[c] * emitFactor) : 0.f;
                maxDiv = a > maxDiv ? a : maxDiv;
                rhs[c] = fluid ? kernels::pressureRhs(div, src[c] * emitFactor, h2) : 0.f;
            }
        }
        planeA[k] = maxDiv;
    });

    const int iterations = std::max(0, st.pressureIterations);
    if (st.pressureSolver == PressureSolver::RedBlackGaussSeidel) {
        float* p = s.pressure.data();
        for (int it = 0; it < iterations; ++it)
            for (int colour = 0; colour < 2; ++colour)
                forPlanes(pool, 1, d.nz - 1, [&](int k) {
                    for (int j = 1; j < d.ny - 1; ++j) {
                        const std::ptrdiff_t row = d.sy * j + d.sz * k;
                        for (int i = 1 + ((1 + j + k + colour) & 1); i < d.nx - 1; i += 2) {
                            const std::ptrdiff_t c = row + i;
                            p[c] = kernels::pressureUpdate(kernels::neighbourSum(p, c, d), rhs[c], dinv[c]);
                        }
                    }
                });
    } else {
        for (int it = 0; it < iterations; ++it) {
            const float* p = s.pressure.data();
            float* q = s.pressureTmp.data();
            forPlanes(pool, 1, d.nz - 1, [&](int k) {
                for (int j = 1; j < d.ny - 1; ++j) {
                    const std::ptrdiff_t row = d.sy * j + d.sz * k;
                    for (int i = 1; i < d.nx - 1; ++i) {
                        const std::ptrdiff_t c = row + i;
                        q[c] = kernels::pressureUpdate(kernels::neighbourSum(p, c, d), rhs[c], dinv[c]);
                    }
                }
            });
            std::swap(s.pressure, s.pressureTmp);
        }
    }
}

void subtractGradient(SmokeState& s, ThreadPool& pool) {
    const Dims d = s.dims;
    const float h = static_cast<float>(s.grid.cellSize), invH = 1.f / h, invH2 = 1.f / (h * h);
    float *u = s.u.data(), *v = s.v.data(), *w = s.w.data();
    const float *p = s.pressure.data(), *rhs = s.rhs.data(), *dinv = s.diagInv.data();
    const std::uint8_t *mu = s.faceMask[0].data(), *mv = s.faceMask[1].data(), *mw = s.faceMask[2].data();
    float* planeB = s.planeB.data();
    forPlanes(pool, 1, d.nz - 1, [&](int k) {
        float maxRes = 0.f;
        for (int j = 1; j < d.ny - 1; ++j) {
            const std::ptrdiff_t row = d.sy * j + d.sz * k;
            for (int i = 1; i < d.nx - 1; ++i) {
                const std::ptrdiff_t c = row + i;
                const float pu = kernels::projectedFace(u[c], p[c], p[c - 1], invH);
                const float pv = kernels::projectedFace(v[c], p[c], p[c - d.sy], invH);
                const float pw = kernels::projectedFace(w[c], p[c], p[c - d.sz], invH);
                u[c] = mu[c] ? pu : 0.f;
                v[c] = mv[c] ? pv : 0.f;
                w[c] = mw[c] ? pw : 0.f;
                if (dinv[c] > 0.f) {  // what the projection leaves: (sum p_nb + rhs - n p) / h^2
                    const float r = std::fabs(kernels::neighbourSum(p, c, d) + rhs[c] - p[c] / dinv[c]) * invH2;
                    maxRes = r > maxRes ? r : maxRes;
                }
            }
        }
        planeB[k] = maxRes;
    });
}

}  // namespace

void projectBorderFaces(SmokeState& s);  // smoke_solver_reference.cpp (shared, O(n^2))

void substepFast(SmokeState& s, const SmokeSettings& st, ThreadPool& pool, float dt) {
    applyEmitter(s, st, dt);
    const float decayD = densityDecay(s, st, dt);
    const float decayT = static_cast<float>(std::exp(-st.temperatureDissipation * dt));
    const float decayV = static_cast<float>(std::exp(-st.velocityDissipation * dt));
    advect(s, st, pool, dt, decayD, decayT, decayV);
    setBorderFaces(s);  // the curl reads the border faces: give them this step's values
    forces(s, st, pool, dt);
    setBorderFaces(s);
    patchDynamicFaces(s);
    const float emitFactor = s.age < st.emitTime ? 1.f : 0.f;
    project(s, st, pool, emitFactor);
    subtractGradient(s, pool);
    projectBorderFaces(s);
    patchDynamicFaces(s);
    float before = 0, after = 0;
    for (int k = 1; k < s.grid.nz - 1; ++k) {
        before = std::max(before, s.planeA[static_cast<std::size_t>(k)]);
        after = std::max(after, s.planeB[static_cast<std::size_t>(k)]);
    }
    s.stats.divergenceBefore = before;
    s.stats.residual = after;
    s.stats.pressureIterations = std::max(0, st.pressureIterations);
}

}  // namespace obscura::smoke
