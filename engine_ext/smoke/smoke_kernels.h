// Per-cell maths of the smoke solver, shared by the optimised (smoke_solver_fast.cpp) and the
// reference (smoke_solver_reference.cpp) paths so both compute each value with the same
// operations in the same order. Everything is float (the fields are float: half the memory
// traffic of double, and plenty for smoke) and free of FMA contraction (-ffp-contract=off).
//
// Staggered (MAC) grid: u[c] is the x velocity on the face between cell c - 1 and cell c (the
// cell's lower x face), v[c] the y velocity on the face between c - sy and c, w[c] likewise in z.
// Index coordinates: cell c = (i, j, k) sits at (i, j, k); its u face at (i - 1/2, j, k). A field
// sampled "in its own index coordinates" puts its sample (i, j, k) at integer (i, j, k).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

// Forced inlining: GCC's -O2 heuristics otherwise leave the sampling helpers as calls, which
// keeps the x loops of the optimised path from vectorising.
#define OBSCURA_SMOKE_INLINE inline __attribute__((always_inline))

namespace obscura::smoke::kernels {

// c ? a : b as a bitwise blend: no branch for the optimiser to thread through, so loops built
// from these stay straight-line and vectorise (an exact select: same bits as the ternary).
OBSCURA_SMOKE_INLINE float sel(bool c, float a, float b) {
    std::uint32_t ia, ib;
    std::memcpy(&ia, &a, 4);
    std::memcpy(&ib, &b, 4);
    const std::uint32_t m = 0u - static_cast<std::uint32_t>(c);
    const std::uint32_t r = (ia & m) | (ib & ~m);
    float o;
    std::memcpy(&o, &r, 4);
    return o;
}
OBSCURA_SMOKE_INLINE float minf(float a, float b) { return b < a ? b : a; }  // minps/maxps in vector code
OBSCURA_SMOKE_INLINE float maxf(float a, float b) { return b > a ? b : a; }

struct Dims {
    int nx, ny, nz;
    std::ptrdiff_t sy, sz;  // strides of j and k (x is contiguous)
};

// Clamp that maps NaN to lo (a comparison with NaN is false), so no NaN index can arise.
OBSCURA_SMOKE_INLINE float clampf(float x, float lo, float hi) { return sel(x > lo, sel(x < hi, x, hi), lo); }

struct Corners {
    std::ptrdiff_t c;      // index of the lower corner
    float fx, fy, fz;      // fractions toward the upper corner
};

// The 2x2x2 block of samples around index coordinates (x, y, z), clamped to the array.
OBSCURA_SMOKE_INLINE Corners corners(const Dims& d, float x, float y, float z) {
    x = clampf(x, 0.f, static_cast<float>(d.nx - 1));
    y = clampf(y, 0.f, static_cast<float>(d.ny - 1));
    z = clampf(z, 0.f, static_cast<float>(d.nz - 1));
    int i = static_cast<int>(x), j = static_cast<int>(y), k = static_cast<int>(z);
    i = i < d.nx - 2 ? i : d.nx - 2;
    j = j < d.ny - 2 ? j : d.ny - 2;
    k = k < d.nz - 2 ? k : d.nz - 2;
    return {i + d.sy * j + d.sz * k, x - static_cast<float>(i), y - static_cast<float>(j), z - static_cast<float>(k)};
}

OBSCURA_SMOKE_INLINE float lerp(float a, float b, float t) { return a + (b - a) * t; }

OBSCURA_SMOKE_INLINE float trilinear(const float* f, const Dims& d, const Corners& q) {
    const float* p = f + q.c;
    const float x00 = lerp(p[0], p[1], q.fx), x10 = lerp(p[d.sy], p[d.sy + 1], q.fx);
    const float x01 = lerp(p[d.sz], p[d.sz + 1], q.fx), x11 = lerp(p[d.sy + d.sz], p[d.sy + d.sz + 1], q.fx);
    return lerp(lerp(x00, x10, q.fy), lerp(x01, x11, q.fy), q.fz);
}

OBSCURA_SMOKE_INLINE float sample(const float* f, const Dims& d, float x, float y, float z) {
    return trilinear(f, d, corners(d, x, y, z));
}

// A backtrace displacement in cells (velocity x dt / h), each axis clamped to one cell: with it,
// every value a trace blends is the starting cell's or a neighbour's toward the trace, so it
// never reaches past a one-cell wall. Scalars, not a struct: GCC keeps struct temporaries of
// `omp simd` loops in memory, which stops the vectoriser.
OBSCURA_SMOKE_INLINE float cells(float velocity, float s) { return clampf(velocity * s, -1.f, 1.f); }

// Velocity components where each field lives (m/s): at a cell centre and on the three faces.
OBSCURA_SMOKE_INLINE float avg2(float a, float b) { return 0.5f * (a + b); }
OBSCURA_SMOKE_INLINE float avg4(float a, float b, float c, float e) { return 0.25f * ((a + b) + (c + e)); }
OBSCURA_SMOKE_INLINE float cellU(const float* u, std::ptrdiff_t c) { return avg2(u[c], u[c + 1]); }
OBSCURA_SMOKE_INLINE float cellV(const float* v, std::ptrdiff_t c, const Dims& d) { return avg2(v[c], v[c + d.sy]); }
OBSCURA_SMOKE_INLINE float cellW(const float* w, std::ptrdiff_t c, const Dims& d) { return avg2(w[c], w[c + d.sz]); }
// On the u face of c (between c - 1 and c): v and w from the four faces around it.
OBSCURA_SMOKE_INLINE float uFaceV(const float* v, std::ptrdiff_t c, const Dims& d) {
    return avg4(v[c - 1], v[c], v[c - 1 + d.sy], v[c + d.sy]);
}
OBSCURA_SMOKE_INLINE float uFaceW(const float* w, std::ptrdiff_t c, const Dims& d) {
    return avg4(w[c - 1], w[c], w[c - 1 + d.sz], w[c + d.sz]);
}
OBSCURA_SMOKE_INLINE float vFaceU(const float* u, std::ptrdiff_t c, const Dims& d) {
    return avg4(u[c - d.sy], u[c], u[c - d.sy + 1], u[c + 1]);
}
OBSCURA_SMOKE_INLINE float vFaceW(const float* w, std::ptrdiff_t c, const Dims& d) {
    return avg4(w[c - d.sy], w[c], w[c - d.sy + d.sz], w[c + d.sz]);
}
OBSCURA_SMOKE_INLINE float wFaceU(const float* u, std::ptrdiff_t c, const Dims& d) {
    return avg4(u[c - d.sz], u[c], u[c - d.sz + 1], u[c + 1]);
}
OBSCURA_SMOKE_INLINE float wFaceV(const float* v, std::ptrdiff_t c, const Dims& d) {
    return avg4(v[c - d.sz], v[c], v[c - d.sz + d.sy], v[c + d.sy]);
}

// Samples within one cell of a grid point. Every advection trace moves at most one cell per axis
// (cells()), so its sample is a trilinear blend of the point's own value and, per axis, ONE
// neighbour: the one toward the displacement, weighted |p|. Written with value selects instead
// of computed indices, so the loops over x vectorise (no gathers) and no index can go astray.
OBSCURA_SMOKE_INLINE float absf(float x) { return sel(x < 0.f, -x, x); }
// The neighbour toward p along one axis (the value itself when p == 0).
OBSCURA_SMOKE_INLINE float toward(float p, float minus, float self, float plus) {
    return sel(p < 0.f, minus, sel(p > 0.f, plus, self));
}

// Per-axis weights of the three samples -1, 0, +1 for a displacement p (|p| <= 1): the sample
// toward p gets |p|, the point itself 1 - |p|, the other 0. Three products per row instead of
// a select-and-lerp keeps the vector code short.
OBSCURA_SMOKE_INLINE float weightMinus(float p) { return sel(p < 0.f, -p, 0.f); }
OBSCURA_SMOKE_INLINE float weightPlus(float p) { return sel(p > 0.f, p, 0.f); }
OBSCURA_SMOKE_INLINE float blend3(float m, float c, float p, float wm, float wc, float wp) { return (wm * m + wc * c) + wp * p; }
OBSCURA_SMOKE_INLINE float row3(const float* f, std::ptrdiff_t r, float wm, float wc, float wp) {
    return blend3(f[r - 1], f[r], f[r + 1], wm, wc, wp);
}
// f at (i, j, k) + (px, py, pz) for the cell/face c = (i, j, k), |p| <= 1 per axis (trilinear).
OBSCURA_SMOKE_INLINE float sampleNear(const float* f, std::ptrdiff_t c, const Dims& d, float px, float py, float pz) {
    const float xm = weightMinus(px), xp = weightPlus(px), xc = 1.f - absf(px);
    const float ym = weightMinus(py), yp = weightPlus(py), yc = 1.f - absf(py);
    const float zm = weightMinus(pz), zp = weightPlus(pz), zc = 1.f - absf(pz);
    const std::ptrdiff_t a = c - d.sz, b = c + d.sz;
    const float below = blend3(row3(f, a - d.sy, xm, xc, xp), row3(f, a, xm, xc, xp), row3(f, a + d.sy, xm, xc, xp), ym, yc, yp);
    const float level = blend3(row3(f, c - d.sy, xm, xc, xp), row3(f, c, xm, xc, xp), row3(f, c + d.sy, xm, xc, xp), ym, yc, yp);
    const float above = blend3(row3(f, b - d.sy, xm, xc, xp), row3(f, b, xm, xc, xp), row3(f, b + d.sy, xm, xc, xp), ym, yc, yp);
    return blend3(below, level, above, zm, zc, zp);
}

// Range (min, max) of the (up to) 2x2x2 values sampleNear blends: MacCormack's clamp bounds
// (Selle et al. 2008).
struct Range {
    float lo, hi;
};
// The block is the rows (j, k), (j', k), (j, k'), (j', k') with j' / k' the neighbours toward
// py / pz (the row itself when 0): select those rows' three x values first, then each row's x
// pair. (min and max are exact, so the grouping does not change a bit of the result.)
OBSCURA_SMOKE_INLINE Range pairRange(float m1, float m0, float p1, float px) {
    const float n = toward(px, m1, m0, p1);
    return {minf(m0, n), maxf(m0, n)};
}
OBSCURA_SMOKE_INLINE Range rangeNear(const float* f, std::ptrdiff_t c, const Dims& d, float px, float py, float pz) {
    const std::ptrdiff_t sy = d.sy, sz = d.sz;
    // Row (j, k).
    const float a0 = f[c - 1], a1 = f[c], a2 = f[c + 1];
    // Row (j', k).
    const float b0 = toward(py, f[c - sy - 1], a0, f[c + sy - 1]);
    const float b1 = toward(py, f[c - sy], a1, f[c + sy]);
    const float b2 = toward(py, f[c - sy + 1], a2, f[c + sy + 1]);
    // Row (j, k').
    const float c0 = toward(pz, f[c - sz - 1], a0, f[c + sz - 1]);
    const float c1 = toward(pz, f[c - sz], a1, f[c + sz]);
    const float c2 = toward(pz, f[c - sz + 1], a2, f[c + sz + 1]);
    // Row (j', k'): toward pz between the rows (j', k - 1), (j', k), (j', k + 1).
    const float e0 = toward(pz, toward(py, f[c - sz - sy - 1], f[c - sz - 1], f[c - sz + sy - 1]), b0,
                            toward(py, f[c + sz - sy - 1], f[c + sz - 1], f[c + sz + sy - 1]));
    const float e1 = toward(pz, toward(py, f[c - sz - sy], f[c - sz], f[c - sz + sy]), b1,
                            toward(py, f[c + sz - sy], f[c + sz], f[c + sz + sy]));
    const float e2 = toward(pz, toward(py, f[c - sz - sy + 1], f[c - sz + 1], f[c - sz + sy + 1]), b2,
                            toward(py, f[c + sz - sy + 1], f[c + sz + 1], f[c + sz + sy + 1]));
    const Range ra = pairRange(a0, a1, a2, px), rb = pairRange(b0, b1, b2, px), rc = pairRange(c0, c1, c2, px),
                re = pairRange(e0, e1, e2, px);
    return {minf(minf(ra.lo, rb.lo), minf(rc.lo, re.lo)), maxf(maxf(ra.hi, rb.hi), maxf(rc.hi, re.hi))};
}

// Semi-Lagrangian forward step: the field at the backtraced point of sample c.
OBSCURA_SMOKE_INLINE float advectForward(const float* f, const Dims& d, std::ptrdiff_t c, float qx, float qy, float qz) {
    return sampleNear(f, c, d, -qx, -qy, -qz);
}

// MacCormack correction (Selle et al. 2008), in two halves the optimised path runs as separate
// loops (fewer live registers): hat + (orig - reverse) / 2, then clamped to the range of the
// source values the forward trace blended.
OBSCURA_SMOKE_INLINE float macCormack(const float* f, const float* hat, const Dims& d, std::ptrdiff_t c, float qx, float qy,
                                      float qz) {
    return hat[c] + 0.5f * (f[c] - sampleNear(hat, c, d, qx, qy, qz));
}
OBSCURA_SMOKE_INLINE float clampToSources(float value, const float* f, const Dims& d, std::ptrdiff_t c, float qx, float qy,
                                          float qz) {
    const Range r = rangeNear(f, c, d, -qx, -qy, -qz);
    return clampf(value, r.lo, r.hi);
}
OBSCURA_SMOKE_INLINE float advectCorrect(const float* f, const float* hat, const Dims& d, std::ptrdiff_t c, float qx,
                                         float qy, float qz) {
    return clampToSources(macCormack(f, hat, d, c, qx, qy, qz), f, d, c, qx, qy, qz);
}

// The trace (in cells, see cells()) of each field's sample c: 0 cell centre, 1/2/3 the u/v/w face.
enum Where { kAtCell = 0, kAtU = 1, kAtV = 2, kAtW = 3 };
template <int W>
OBSCURA_SMOKE_INLINE void traceAt(const float* u, const float* v, const float* w, std::ptrdiff_t c, const Dims& d, float s,
                                  float& qx, float& qy, float& qz) {
    if constexpr (W == kAtU) {
        qx = cells(u[c], s), qy = cells(uFaceV(v, c, d), s), qz = cells(uFaceW(w, c, d), s);
    } else if constexpr (W == kAtV) {
        qx = cells(vFaceU(u, c, d), s), qy = cells(v[c], s), qz = cells(vFaceW(w, c, d), s);
    } else if constexpr (W == kAtW) {
        qx = cells(wFaceU(u, c, d), s), qy = cells(wFaceV(v, c, d), s), qz = cells(w[c], s);
    } else {
        qx = cells(cellU(u, c), s), qy = cells(cellV(v, c, d), s), qz = cells(cellW(w, c, d), s);
    }
}

OBSCURA_SMOKE_INLINE float centreU(const float* u, std::ptrdiff_t n) { return 0.5f * (u[n] + u[n + 1]); }
OBSCURA_SMOKE_INLINE float centreV(const float* v, std::ptrdiff_t n, const Dims& d) { return 0.5f * (v[n] + v[n + d.sy]); }
OBSCURA_SMOKE_INLINE float centreW(const float* w, std::ptrdiff_t n, const Dims& d) { return 0.5f * (w[n] + w[n + d.sz]); }
OBSCURA_SMOKE_INLINE void curlAt(const float* u, const float* v, const float* w, std::ptrdiff_t c, const Dims& d,
                                 float halfInvH, float& ox, float& oy, float& oz) {
    ox = ((centreW(w, c + d.sy, d) - centreW(w, c - d.sy, d)) - (centreV(v, c + d.sz, d) - centreV(v, c - d.sz, d))) * halfInvH;
    oy = ((centreU(u, c + d.sz) - centreU(u, c - d.sz)) - (centreW(w, c + 1, d) - centreW(w, c - 1, d))) * halfInvH;
    oz = ((centreV(v, c + 1, d) - centreV(v, c - 1, d)) - (centreU(u, c + d.sy) - centreU(u, c - d.sy))) * halfInvH;
}

// Vorticity confinement force (Fedkiw, Stam, Jensen 2001): eps * h * (N x omega), N the unit
// gradient of |omega|. mag holds |omega| per cell.
OBSCURA_SMOKE_INLINE void confinementAt(const float* mag, std::ptrdiff_t c, const Dims& d, float halfInvH, float epsH, float ox,
                          float oy, float oz, float& fx, float& fy, float& fz) {
    const float gx = (mag[c + 1] - mag[c - 1]) * halfInvH;
    const float gy = (mag[c + d.sy] - mag[c - d.sy]) * halfInvH;
    const float gz = (mag[c + d.sz] - mag[c - d.sz]) * halfInvH;
    const float len = std::sqrt(gx * gx + gy * gy + gz * gz) + 1e-20f;  // 1e-20: no 0/0 in still air
    const float s = epsH / len;
    fx = (gy * oz - gz * oy) * s;
    fy = (gz * ox - gx * oz) * s;
    fz = (gx * oy - gy * ox) * s;
}

OBSCURA_SMOKE_INLINE float magnitude(float x, float y, float z) { return std::sqrt(x * x + y * y + z * z); }

// Face velocity after the body forces: the two cells' forces averaged onto the face, clamped.
OBSCURA_SMOKE_INLINE float forcedFace(float vel, float forceA, float forceB, float dt, float vmax) {
    return clampf(vel + dt * (0.5f * (forceA + forceB)), -vmax, vmax);
}
// Upward acceleration of a cell from its temperature and density (Fedkiw et al. 2001), added to
// its vertical confinement force before averaging onto the y faces.
OBSCURA_SMOKE_INLINE float cellLift(float confinementY, float temperature, float density, float buoyancy, float weight) {
    return confinementY + (buoyancy * temperature - weight * density);
}

// Discrete divergence of cell c (1/s).
OBSCURA_SMOKE_INLINE float divergenceAt(const float* u, const float* v, const float* w, std::ptrdiff_t c, const Dims& d, float invH) {
    return ((u[c + 1] - u[c]) + (v[c + d.sy] - v[c]) + (w[c + d.sz] - w[c])) * invH;
}

// Pressure equation right-hand side for a fluid cell: sum(p_nb) - n p = h^2 (div - source).
OBSCURA_SMOKE_INLINE float pressureRhs(float divergence, float source, float h2) { return (source - divergence) * h2; }

// One Jacobi / Gauss-Seidel update from the neighbour sum (order: -x, +x, -y, +y, -z, +z, with
// solid neighbours contributing exactly 0) and 1 / (number of non-solid neighbours).
OBSCURA_SMOKE_INLINE float pressureUpdate(float neighbourSum, float rhs, float diagInv) { return diagInv * (neighbourSum + rhs); }

OBSCURA_SMOKE_INLINE float neighbourSum(const float* p, std::ptrdiff_t c, const Dims& d) {
    return ((((p[c - 1] + p[c + 1]) + p[c - d.sy]) + p[c + d.sy]) + p[c - d.sz]) + p[c + d.sz];
}

// Face velocity after subtracting the pressure gradient (only faces between a fluid cell and a
// non-solid one; others are set by the boundary conditions).
OBSCURA_SMOKE_INLINE float projectedFace(float vel, float pHere, float pBehind, float invH) { return vel - (pHere - pBehind) * invH; }

}  // namespace obscura::smoke::kernels
