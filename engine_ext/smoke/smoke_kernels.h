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

namespace obscura::smoke::kernels {

struct Dims {
    int nx, ny, nz;
    std::ptrdiff_t sy, sz;  // strides of j and k (x is contiguous)
};

// Clamp that maps NaN to lo (a comparison with NaN is false), so no NaN index can arise.
inline float clampf(float x, float lo, float hi) { return x > lo ? (x < hi ? x : hi) : lo; }

struct Corners {
    std::ptrdiff_t c;      // index of the lower corner
    float fx, fy, fz;      // fractions toward the upper corner
};

// The 2x2x2 block of samples around index coordinates (x, y, z), clamped to the array.
inline Corners corners(const Dims& d, float x, float y, float z) {
    x = clampf(x, 0.f, static_cast<float>(d.nx - 1));
    y = clampf(y, 0.f, static_cast<float>(d.ny - 1));
    z = clampf(z, 0.f, static_cast<float>(d.nz - 1));
    int i = static_cast<int>(x), j = static_cast<int>(y), k = static_cast<int>(z);
    i = i < d.nx - 2 ? i : d.nx - 2;
    j = j < d.ny - 2 ? j : d.ny - 2;
    k = k < d.nz - 2 ? k : d.nz - 2;
    return {i + d.sy * j + d.sz * k, x - static_cast<float>(i), y - static_cast<float>(j), z - static_cast<float>(k)};
}

inline float lerp(float a, float b, float t) { return a + (b - a) * t; }

inline float trilinear(const float* f, const Dims& d, const Corners& q) {
    const float* p = f + q.c;
    const float x00 = lerp(p[0], p[1], q.fx), x10 = lerp(p[d.sy], p[d.sy + 1], q.fx);
    const float x01 = lerp(p[d.sz], p[d.sz + 1], q.fx), x11 = lerp(p[d.sy + d.sz], p[d.sy + d.sz + 1], q.fx);
    return lerp(lerp(x00, x10, q.fy), lerp(x01, x11, q.fy), q.fz);
}

inline float sample(const float* f, const Dims& d, float x, float y, float z) {
    return trilinear(f, d, corners(d, x, y, z));
}

// The eight source values' range, for MacCormack's clamp (Selle et al. 2008).
inline void cornerRange(const float* f, const Dims& d, const Corners& q, float& lo, float& hi) {
    const float* p = f + q.c;
    const float v[8] = {p[0], p[1], p[d.sy], p[d.sy + 1], p[d.sz], p[d.sz + 1], p[d.sy + d.sz], p[d.sy + d.sz + 1]};
    lo = v[0];
    hi = v[0];
    for (int n = 1; n < 8; ++n) {
        lo = v[n] < lo ? v[n] : lo;
        hi = v[n] > hi ? v[n] : hi;
    }
}

// A backtrace displacement in cells, each axis clamped to one cell: with it, the 2x2x2 block a
// trace samples always contains the starting cell, so it never reaches past a one-cell wall.
struct Disp {
    float x, y, z;
};
inline Disp clampDisp(float x, float y, float z) {
    return {clampf(x, -1.f, 1.f), clampf(y, -1.f, 1.f), clampf(z, -1.f, 1.f)};
}

// Velocity (scaled by s = dt / h, so in cells) at the centre of cell c and at its three faces.
inline Disp dispAtCell(const float* u, const float* v, const float* w, std::ptrdiff_t c, const Dims& d, float s) {
    return clampDisp(0.5f * (u[c] + u[c + 1]) * s, 0.5f * (v[c] + v[c + d.sy]) * s, 0.5f * (w[c] + w[c + d.sz]) * s);
}
inline Disp dispAtU(const float* u, const float* v, const float* w, std::ptrdiff_t c, const Dims& d, float s) {
    const float vy = 0.25f * ((v[c - 1] + v[c]) + (v[c - 1 + d.sy] + v[c + d.sy]));
    const float wz = 0.25f * ((w[c - 1] + w[c]) + (w[c - 1 + d.sz] + w[c + d.sz]));
    return clampDisp(u[c] * s, vy * s, wz * s);
}
inline Disp dispAtV(const float* u, const float* v, const float* w, std::ptrdiff_t c, const Dims& d, float s) {
    const float ux = 0.25f * ((u[c - d.sy] + u[c]) + (u[c - d.sy + 1] + u[c + 1]));
    const float wz = 0.25f * ((w[c - d.sy] + w[c]) + (w[c - d.sy + d.sz] + w[c + d.sz]));
    return clampDisp(ux * s, v[c] * s, wz * s);
}
inline Disp dispAtW(const float* u, const float* v, const float* w, std::ptrdiff_t c, const Dims& d, float s) {
    const float ux = 0.25f * ((u[c - d.sz] + u[c]) + (u[c - d.sz + 1] + u[c + 1]));
    const float vy = 0.25f * ((v[c - d.sz] + v[c]) + (v[c - d.sz + d.sy] + v[c + d.sy]));
    return clampDisp(ux * s, vy * s, w[c] * s);
}

// Semi-Lagrangian forward step: the field at the backtraced point of sample (i, j, k).
inline float advectForward(const float* f, const Dims& d, int i, int j, int k, const Disp& q) {
    return sample(f, d, static_cast<float>(i) - q.x, static_cast<float>(j) - q.y, static_cast<float>(k) - q.z);
}

// MacCormack correction: hat + (orig - reverse) / 2, clamped to the source cells' range.
inline float advectCorrect(const float* f, const float* hat, const Dims& d, std::ptrdiff_t c, int i, int j, int k,
                           const Disp& q) {
    const float fi = static_cast<float>(i), fj = static_cast<float>(j), fk = static_cast<float>(k);
    const float reverse = sample(hat, d, fi + q.x, fj + q.y, fk + q.z);
    float lo, hi;
    cornerRange(f, d, corners(d, fi - q.x, fj - q.y, fk - q.z), lo, hi);
    return clampf(hat[c] + 0.5f * (f[c] - reverse), lo, hi);
}

// Curl of the cell-centred velocity at cell c (central differences; halfInvH = 0.5 / h).
inline void curlAt(const float* u, const float* v, const float* w, std::ptrdiff_t c, const Dims& d, float halfInvH,
                   float& ox, float& oy, float& oz) {
    auto U = [&](std::ptrdiff_t n) { return 0.5f * (u[n] + u[n + 1]); };
    auto V = [&](std::ptrdiff_t n) { return 0.5f * (v[n] + v[n + d.sy]); };
    auto W = [&](std::ptrdiff_t n) { return 0.5f * (w[n] + w[n + d.sz]); };
    ox = ((W(c + d.sy) - W(c - d.sy)) - (V(c + d.sz) - V(c - d.sz))) * halfInvH;
    oy = ((U(c + d.sz) - U(c - d.sz)) - (W(c + 1) - W(c - 1))) * halfInvH;
    oz = ((V(c + 1) - V(c - 1)) - (U(c + d.sy) - U(c - d.sy))) * halfInvH;
}

// Vorticity confinement force (Fedkiw, Stam, Jensen 2001): eps * h * (N x omega), N the unit
// gradient of |omega|. mag holds |omega| per cell.
inline void confinementAt(const float* mag, std::ptrdiff_t c, const Dims& d, float halfInvH, float epsH, float ox,
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

inline float magnitude(float x, float y, float z) { return std::sqrt(x * x + y * y + z * z); }

// Face velocity after the body forces: the two cells' forces averaged onto the face, clamped.
inline float forcedFace(float vel, float forceA, float forceB, float dt, float vmax) {
    return clampf(vel + dt * (0.5f * (forceA + forceB)), -vmax, vmax);
}
// Upward acceleration of a cell from its temperature and density (Fedkiw et al. 2001), added to
// its vertical confinement force before averaging onto the y faces.
inline float cellLift(float confinementY, float temperature, float density, float buoyancy, float weight) {
    return confinementY + (buoyancy * temperature - weight * density);
}

// Discrete divergence of cell c (1/s).
inline float divergenceAt(const float* u, const float* v, const float* w, std::ptrdiff_t c, const Dims& d, float invH) {
    return ((u[c + 1] - u[c]) + (v[c + d.sy] - v[c]) + (w[c + d.sz] - w[c])) * invH;
}

// Pressure equation right-hand side for a fluid cell: sum(p_nb) - n p = h^2 (div - source).
inline float pressureRhs(float divergence, float source, float h2) { return (source - divergence) * h2; }

// One Jacobi / Gauss-Seidel update from the neighbour sum (order: -x, +x, -y, +y, -z, +z, with
// solid neighbours contributing exactly 0) and 1 / (number of non-solid neighbours).
inline float pressureUpdate(float neighbourSum, float rhs, float diagInv) { return diagInv * (neighbourSum + rhs); }

inline float neighbourSum(const float* p, std::ptrdiff_t c, const Dims& d) {
    return ((((p[c - 1] + p[c + 1]) + p[c - d.sy]) + p[c + d.sy]) + p[c - d.sz]) + p[c + d.sz];
}

// Face velocity after subtracting the pressure gradient (only faces between a fluid cell and a
// non-solid one; others are set by the boundary conditions).
inline float projectedFace(float vel, float pHere, float pBehind, float invH) { return vel - (pHere - pBehind) * invH; }

}  // namespace obscura::smoke::kernels
