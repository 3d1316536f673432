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
#include <type_traits>

// Forced inlining: GCC's -O2 heuristics otherwise leave the sampling helpers as calls, which
// keeps the x loops of the optimised path from vectorising.
#define OBSCURA_SMOKE_INLINE inline __attribute__((always_inline))
// `omp simd` on loops shared with the reference path: only where the file is built with
// -fopenmp-simd (smoke_solver_fast.cpp defines OBSCURA_SMOKE_SIMD); the reference stays scalar.
#ifdef OBSCURA_SMOKE_SIMD
#define OBSCURA_SMOKE_SIMD_LOOP _Pragma("omp simd")
#define OBSCURA_SMOKE_SIMD_MAX_M _Pragma("omp simd reduction(max : m)")  // a max reduction into `m`
#else
#define OBSCURA_SMOKE_SIMD_LOOP
#define OBSCURA_SMOKE_SIMD_MAX_M
#endif

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
// (cells()), so its sample is a trilinear blend of a 2x2x2 block: per axis the point's own value
// and ONE neighbour, the one toward the displacement, weighted |p|. The block is picked out of the
// 27 values around the point with value selects instead of computed indices: no gathers, and no
// index can go astray. Templated on the value type: F = float for the reference path, a vector of
// floats (GCC vector extension) for the optimised one, which runs the same expressions lane by
// lane and so gives the same bits. (Where a whole vector traces the same way it loads the block
// directly and does the same arithmetic: smoke_solver_fast_impl.h.)
OBSCURA_SMOKE_INLINE float absf(float x) { return sel(x < 0.f, -x, x); }
template <class F>
OBSCURA_SMOKE_INLINE F loadT(const float* p) {
    if constexpr (std::is_same_v<F, float>) {
        return *p;
    } else {
        F v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
}
template <class F>
OBSCURA_SMOKE_INLINE F absT(F x) { return x < F{} ? -x : x; }  // as absf
// The neighbour toward p along one axis (the value itself when p == 0).
template <class F>
OBSCURA_SMOKE_INLINE F towardT(F p, F minus, F self, F plus) { return p < F{} ? minus : (p > F{} ? plus : self); }
// o[k] or its z-neighbour toward pz.
template <class F>
OBSCURA_SMOKE_INLINE F towardZ(const float* o, std::ptrdiff_t k, std::ptrdiff_t sz, F pz) {
    return towardT(pz, loadT<F>(o + k - sz), loadT<F>(o + k), loadT<F>(o + k + sz));
}

// The block around the sample at o for a displacement (px, py, pz), |p| <= 1 per axis: a* in the
// sample's own z plane, b* in the plane toward pz; *0 the own column, *1 the x neighbour's, *2
// the y neighbour's, *3 the diagonal one. The z choice is made on the nine columns first.
template <class F>
OBSCURA_SMOKE_INLINE void blockNear(const float* o, const Dims& d, F px, F py, F pz, F& a0, F& a1, F& a2, F& a3, F& b0, F& b1,
                                    F& b2, F& b3) {
    const std::ptrdiff_t sy = d.sy, sz = d.sz;
    auto at = [o](std::ptrdiff_t k) { return loadT<F>(o + k); };
    a0 = at(0);
    a1 = towardT(px, at(-1), a0, at(1));
    a2 = towardT(py, at(-sy), a0, at(sy));
    a3 = towardT(py, towardT(px, at(-sy - 1), at(-sy), at(-sy + 1)), a1, towardT(px, at(sy - 1), at(sy), at(sy + 1)));
    b0 = towardZ(o, 0, sz, pz);
    b1 = towardT(px, towardZ(o, -1, sz, pz), b0, towardZ(o, 1, sz, pz));
    const F bm = towardZ(o, -sy, sz, pz), bp = towardZ(o, sy, sz, pz);
    b2 = towardT(py, bm, b0, bp);
    b3 = towardT(py, towardT(px, towardZ(o, -sy - 1, sz, pz), bm, towardZ(o, -sy + 1, sz, pz)), b1,
                 towardT(px, towardZ(o, sy - 1, sz, pz), bp, towardZ(o, sy + 1, sz, pz)));
}

// Trilinear blend of a block with the weights |p|: x, then y, then z (with p == 0 on an axis the
// lerps return the own value); and the block's minimum and maximum, in one fixed grouping (min
// and max are exact, but the sign of a zero depends on the order).
template <class F>
OBSCURA_SMOKE_INLINE F lerpT(F a, F b, F t) { return a + (b - a) * t; }
template <class F>
OBSCURA_SMOKE_INLINE F minT(F a, F b) { return b < a ? b : a; }
template <class F>
OBSCURA_SMOKE_INLINE F maxT(F a, F b) { return b > a ? b : a; }
template <class F>
OBSCURA_SMOKE_INLINE F blendBlock(F a0, F a1, F a2, F a3, F b0, F b1, F b2, F b3, F ax, F ay, F az) {
    const F a = lerpT(lerpT(a0, a1, ax), lerpT(a2, a3, ax), ay);
    const F b = lerpT(lerpT(b0, b1, ax), lerpT(b2, b3, ax), ay);
    return lerpT(a, b, az);
}
template <class F>
OBSCURA_SMOKE_INLINE F blockMin(F a0, F a1, F a2, F a3, F b0, F b1, F b2, F b3) {
    return minT(minT(minT(a0, a1), minT(a2, a3)), minT(minT(b0, b1), minT(b2, b3)));
}
template <class F>
OBSCURA_SMOKE_INLINE F blockMax(F a0, F a1, F a2, F a3, F b0, F b1, F b2, F b3) {
    return maxT(maxT(maxT(a0, a1), maxT(a2, a3)), maxT(maxT(b0, b1), maxT(b2, b3)));
}

// The field at the sample at o displaced by (px, py, pz), |p| <= 1 per axis (trilinear).
template <class F>
OBSCURA_SMOKE_INLINE F sampleNearT(const float* o, const Dims& d, F px, F py, F pz) {
    F a0, a1, a2, a3, b0, b1, b2, b3;
    blockNear(o, d, px, py, pz, a0, a1, a2, a3, b0, b1, b2, b3);
    return blendBlock(a0, a1, a2, a3, b0, b1, b2, b3, absT(px), absT(py), absT(pz));
}
// Range (lo, hi) of the block sampleNearT blends: MacCormack's clamp bounds (Selle et al. 2008).
template <class F>
OBSCURA_SMOKE_INLINE void rangeNearT(const float* o, const Dims& d, F px, F py, F pz, F& lo, F& hi) {
    F a0, a1, a2, a3, b0, b1, b2, b3;
    blockNear(o, d, px, py, pz, a0, a1, a2, a3, b0, b1, b2, b3);
    lo = blockMin(a0, a1, a2, a3, b0, b1, b2, b3);
    hi = blockMax(a0, a1, a2, a3, b0, b1, b2, b3);
}
OBSCURA_SMOKE_INLINE float sampleNear(const float* f, std::ptrdiff_t c, const Dims& d, float px, float py, float pz) {
    return sampleNearT(f + c, d, px, py, pz);
}

// Semi-Lagrangian forward step: the field at the backtraced point of sample c.
OBSCURA_SMOKE_INLINE float advectForward(const float* f, const Dims& d, std::ptrdiff_t c, float qx, float qy, float qz) {
    return sampleNear(f, c, d, -qx, -qy, -qz);
}

// MacCormack correction (Selle et al. 2008): hat + (orig - reverse) / 2, then clamped to the range
// of the source values the forward trace blended. Templated halves: the optimised path's vectors
// run the same expressions.
template <class F>
OBSCURA_SMOKE_INLINE F macCormackValue(F hat, F orig, F reverse) { return hat + 0.5f * (orig - reverse); }
template <class F>
OBSCURA_SMOKE_INLINE F clampT(F x, F lo, F hi) { return x > lo ? (x < hi ? x : hi) : lo; }  // as clampf
OBSCURA_SMOKE_INLINE float macCormack(const float* f, const float* hat, const Dims& d, std::ptrdiff_t c, float qx, float qy,
                                      float qz) {
    return macCormackValue(hat[c], f[c], sampleNear(hat, c, d, qx, qy, qz));
}
OBSCURA_SMOKE_INLINE float clampToSources(float value, const float* f, const Dims& d, std::ptrdiff_t c, float qx, float qy,
                                          float qz) {
    float lo, hi;
    rangeNearT(f + c, d, -qx, -qy, -qz, lo, hi);
    return clampT(value, lo, hi);
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

// ---- Flux-form transport of the cell-centred scalars (density, temperature) ----
// Finite volumes: the amount in a cell changes only by what crosses its six faces, and what one
// cell loses through a face its neighbour gains, so the total changes only through the open
// border and the modelled sources and decays (to float round-off). The face value is the donor
// (upwind) cell's value plus a limited slope times (1 - |courant|) / 2 (Lax-Wendroff in time, the
// monotonized-central limiter of van Leer 1977 in space: second order where the field is smooth,
// no new extremum along the axis). Positivity: each face's value is capped at donor / (the donor's
// total outflow courant), so no cell ever sends out more than it holds, whatever the time step.

// The face fluxes are templated like the MacCormack blocks above: F = float (and M = bool) for
// the reference path, F = a vector of floats (M = its comparison mask) for the optimised one,
// which runs the same expressions lane by lane and so gives the same bits. (Plain `omp simd` loops
// of these do not vectorise: GCC sinks arithmetic into a ternary's arms, and a conditional float
// operation may trap, so it will not if-convert them.)

// MC-limited slope from the backward and forward differences (0 at an extremum).
// (Signs compared, not multiplied: the product of two tiny differences would be subnormal, and
// subnormal arithmetic runs ~100x slower on x86.)
template <class F>
OBSCURA_SMOKE_INLINE F mcSlopeT(F back, F fwd) {
    const F two = F{} + 2.f, half = F{} + 0.5f, zero = F{};
    const F m = minT(minT(absT(two * back), absT(two * fwd)), absT(half * (back + fwd)));
    const auto up = (back > zero) & (fwd > zero), down = (back < zero) & (fwd < zero);
    return up ? m : (down ? -m : zero);
}

// A face's speed out of the cell on one side: the speed if it leaves that cell through an open face.
template <class F, class M>
OBSCURA_SMOKE_INLINE F outOfT(F speed, M open) { return open & (speed > F{}) ? speed : F{}; }
// A fluid cell's outflow rate (1/s; 0 for any other cell): its outward face speeds over h, for
// open faces. Inputs: the lower and upper face velocities per axis and their masks.
template <class F, class M>
OBSCURA_SMOKE_INLINE F outflowRateT(F uLo, F uHi, F vLo, F vHi, F wLo, F wHi, M muLo, M muHi, M mvLo, M mvHi, M mwLo, M mwHi,
                                    M fluid, F invH) {
    const F sum = ((outOfT(-uLo, muLo) + outOfT(uHi, muHi)) + (outOfT(-vLo, mvLo) + outOfT(vHi, mvHi))) +
                  (outOfT(-wLo, mwLo) + outOfT(wHi, mwHi));
    return fluid ? sum * invH : F{};
}
// The outflow cap of a cell for a step of dt: 1 / its total outflow courant number (1e-20: a cell
// at rest sends nothing, no cap needed; a cell that is not fluid has rate 0 and holds no smoke).
template <class F>
OBSCURA_SMOKE_INLINE F outflowCapT(F rate, float dt) {
    const F courant = rate * dt, tiny = F{} + 1e-20f;
    return (F{} + 1.f) / (courant > tiny ? courant : tiny);
}

// The value a scalar carries through a face: the donor (upwind) cell's value plus its MC slope
// times (1 - |courant|) / 2 toward the face, at most donor x the donor's outflow cap.
// (a, b | d, e): the field at the two cells below the face and the two above (b and d share it).
template <class F, class M>
OBSCURA_SMOKE_INLINE F faceValueT(M positive, M backOpen, F lw, F cap, F a, F b, F d, F e) {
    const F donor = positive ? b : d, ahead = positive ? d : b, behind = positive ? a : e;
    const F slope = mcSlopeT(backOpen ? donor - behind : F{}, ahead - donor);
    return minT(donor + lw * slope, donor * cap);
}
// Both scalars' fluxes through one face (amount per cell volume, positive toward +axis).
// courant = face velocity x dt / h; open: the face mask; openLo / openHi: the masks of the faces
// below b and above d; capB / capD: outflowCap of b and d.
template <class F, class M>
OBSCURA_SMOKE_INLINE void faceFluxesT(F courant, M open, M openLo, M openHi, F capB, F capD, F da, F db, F dd, F de, F ta, F tb,
                                      F td, F te, F& densityFlux, F& temperatureFlux) {
    const F zero = F{}, one = F{} + 1.f;
    const M positive = courant > zero;
    const M backOpen = positive ? openLo : openHi;
    const F speed = absT(courant);
    const F lw = (F{} + 0.5f) * (speed < one ? one - speed : zero);  // >= 0: no reversed correction past courant 1
    const F cap = positive ? capB : capD;  // the donor's
    const F fd = courant * faceValueT(positive, backOpen, lw, cap, da, db, dd, de);
    const F ft = courant * faceValueT(positive, backOpen, lw, cap, ta, tb, td, te);
    densityFlux = open ? fd : zero;
    temperatureFlux = open ? ft : zero;
}
OBSCURA_SMOKE_INLINE void faceFluxes(float courant, bool open, bool openLo, bool openHi, float capB, float capD, float da,
                                     float db, float dd, float de, float ta, float tb, float td, float te, float& densityFlux,
                                     float& temperatureFlux) {
    faceFluxesT<float, bool>(courant, open, openLo, openHi, capB, capD, da, db, dd, de, ta, tb, td, te, densityFlux, temperatureFlux);
}
// A cell's new value from its six face fluxes (lower, upper per axis), then the modelled decay.
// Values under kTiny become 0: the outflow cap keeps the sum >= 0 up to the rounding of the cap
// itself, and the transport's far tails would otherwise decay into subnormal floats (~100x slower
// arithmetic on x86; measured: 5 % of a 64^3 cloud's cells after 1.5 s). What this drops is below
// 1e-20 a cell: 1e-14 of a cloud's total at 64^3, under float rounding.
constexpr float kTiny = 1e-20f;
OBSCURA_SMOKE_INLINE float fluxUpdate(float value, float xLo, float xHi, float yLo, float yHi, float zLo, float zHi, float decay) {
    const float v = (value + (((xLo - xHi) + (yLo - yHi)) + (zLo - zHi))) * decay;
    return sel(v > kTiny, v, 0.f);
}

// ---- Multigrid-preconditioned conjugate gradients (McAdams, Sifakis, Teran 2010) ----
// Operator on every level: (A x)_c = diag_c x_c - sum over faces of coef_f x_neighbour, with x = 0
// outside the unknowns. Level 0 has unit coefficients (faces between fluid cells) and diag = the
// number of non-solid neighbours (open ones are Dirichlet p = 0); coarser levels carry their own.
OBSCURA_SMOKE_INLINE float coarseNeighbours(const float* x, const float* cx, const float* cy, const float* cz, std::ptrdiff_t c,
                                            std::ptrdiff_t sy, std::ptrdiff_t sz) {
    return ((((cx[c] * x[c - 1] + cx[c + 1] * x[c + 1]) + cy[c] * x[c - sy]) + cy[c + sy] * x[c + sy]) + cz[c] * x[c - sz]) +
           cz[c + sz] * x[c + sz];
}
// Damped Jacobi: x + omega (D^-1 (b + neighbours) - x); unknowns only (dinv 0 elsewhere keeps 0).
OBSCURA_SMOKE_INLINE float jacobiStep(float x, float neighbours, float b, float dinv, float omega) {
    return x + omega * (dinv * (b + neighbours) - x);
}
OBSCURA_SMOKE_INLINE float jacobiFromZero(float b, float dinv, float omega) { return omega * (dinv * b); }
// b - A x at an unknown, 0 elsewhere.
OBSCURA_SMOKE_INLINE float residualAt(float b, float diag, float x, float neighbours, float dinv) {
    return sel(dinv > 0.f, b - (diag * x - neighbours), 0.f);
}
OBSCURA_SMOKE_INLINE float applyAt(float diag, float x, float neighbours, float dinv) {
    return sel(dinv > 0.f, diag * x - neighbours, 0.f);
}
// The 8 children of a coarse cell summed in one fixed order (restriction).
OBSCURA_SMOKE_INLINE float sum8(const float* r, std::ptrdiff_t c, std::ptrdiff_t sy, std::ptrdiff_t sz) {
    return ((r[c] + r[c + 1]) + (r[c + sy] + r[c + sy + 1])) + ((r[c + sz] + r[c + sz + 1]) + (r[c + sz + sy] + r[c + sz + sy + 1]));
}
// Sum of x[i] * y[i] over a row of n values in one canonical order: 8 interleaved partial sums
// (lane i mod 8), combined pairwise. Every build and path sums in this order, so dot products -
// and with them CG's step lengths - are bitwise the same for SSE2, AVX2 and the reference.
OBSCURA_SMOKE_INLINE float rowDot(const float* x, const float* y, int n) {
    float lane[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        OBSCURA_SMOKE_SIMD_LOOP
        for (int l = 0; l < 8; ++l) lane[l] += x[i + l] * y[i + l];
    }
    for (; i < n; ++i) lane[i & 7] += x[i] * y[i];
    return ((lane[0] + lane[1]) + (lane[2] + lane[3])) + ((lane[4] + lane[5]) + (lane[6] + lane[7]));
}

// Face velocity after subtracting the pressure gradient (only faces between a fluid cell and a
// non-solid one; others are set by the boundary conditions).
OBSCURA_SMOKE_INLINE float projectedFace(float vel, float pHere, float pBehind, float invH) { return vel - (pHere - pBehind) * invH; }

}  // namespace obscura::smoke::kernels
