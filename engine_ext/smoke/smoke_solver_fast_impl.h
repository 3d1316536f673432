// The optimised substep's body, included twice by smoke_solver_fast.cpp: once for the baseline
// x86-64 instruction set and once under `#pragma GCC target("avx2")`, each inside its own
// namespace; the caller picks one at run time. Not a standalone header: the includer provides
// the std headers, smoke_state.h and thread_pool.h, and the enclosing namespace.
//
// z-slabs on the thread pool, fused passes (the scalars' fluxes and the velocity's forward step in
// one sweep, their updates in the next; forces and boundary conditions in one), branch-free
// boundary handling through the precomputed face masks and diagInv, x-contiguous inner loops. Every value is computed by the same kernel
// (smoke_kernels.h) as in the reference path; reductions go through per-z-plane partials combined
// in plane order, so the thread count never changes a bit of the result.
namespace {

using kernels::Dims;

template <class Fn>
void forPlanes(ThreadPool& pool, int k0, int k1, const Fn& fn) {  // planes [k0, k1)
    pool.parallelFor(k1 - k0, [&](int b, int e) {
        for (int k = k0 + b; k < k0 + e; ++k) fn(k);
    });
}

// Row kernels: everything they use arrives by value, so the compiler can keep it in registers
// (stores to float arrays could otherwise alias a captured float and force reloads that stop
// the vectoriser). Each processes x in [i0, i1) of one row starting at index `row`.
struct Velocity {
    const float *u, *v, *w;
};
struct VelocityOut {
    float *u, *v, *w;
};

// Each velocity component gets its own loop over the row (the row's data stays in L1): one fused
// loop over all of them needs more live vectors than there are registers and spills. The trace
// of a row's samples is computed once into scratch rows and shared by both MacCormack passes.
struct Trace {
    float *x, *y, *z;
};

template <int W>
void traceRow(const float* u, const float* v, const float* w, Dims d, float s, std::ptrdiff_t row, int i0, int i1, Trace q) {
    float *qx = q.x, *qy = q.y, *qz = q.z;
#pragma omp simd
    for (int i = i0; i < i1; ++i) {
        float x, y, z;
        kernels::traceAt<W>(u, v, w, row + i, d, s, x, y, z);
        qx[i] = x;
        qy[i] = y;
        qz[i] = z;
    }
}

// The two MacCormack passes run on explicit vectors of OBSCURA_SMOKE_LANES floats (GCC vector
// extensions) through the kernels' templated expressions, so every lane gives the bits the scalar
// reference gives. In a smooth flow the samples of a vector nearly always trace toward the same
// octant, or do not move (measured: 90 % of the vectors in the benchmark's cloud); then the block
// is eight loads at the same offsets for every lane and the 38 selects that pick it out of 27
// values go away. Vectors with mixed directions take the selects.
constexpr int kLanes = OBSCURA_SMOKE_LANES;
typedef float VecF __attribute__((vector_size(4 * kLanes)));
typedef std::int32_t VecI __attribute__((vector_size(4 * kLanes)));

OBSCURA_SMOKE_INLINE VecF load(const float* p) { return kernels::loadT<VecF>(p); }
OBSCURA_SMOKE_INLINE void store(float* p, VecF v) { std::memcpy(p, &v, sizeof v); }

// The step to the neighbour every lane's displacement p points to along an axis with this stride
// (-stride, +stride, or 0 when no lane moves), or false when the lanes differ.
OBSCURA_SMOKE_INLINE bool commonStep(VecF p, std::ptrdiff_t stride, std::ptrdiff_t& step) {
    constexpr int all = (1 << kLanes) - 1;
    const VecI negative = p < VecF{}, positive = p > VecF{};
    const int neg = OBSCURA_SMOKE_MOVEMASK(negative), pos = OBSCURA_SMOKE_MOVEMASK(positive);
    if (neg == all) step = -stride;
    else if (pos == all) step = stride;
    else if ((neg | pos) == 0) step = 0;
    else return false;
    return true;
}
struct Steps {
    bool common;
    std::ptrdiff_t x, y, z;
};
OBSCURA_SMOKE_INLINE Steps commonSteps(VecF px, VecF py, VecF pz, const Dims& d) {
    Steps s{};
    s.common = commonStep(px, 1, s.x) && commonStep(py, d.sy, s.y) && commonStep(pz, d.sz, s.z);
    return s;
}

// The block kernels::blockNear would pick, loaded at the common steps.
OBSCURA_SMOKE_INLINE void blockAt(const float* o, std::ptrdiff_t sx, std::ptrdiff_t sy, std::ptrdiff_t sz, VecF& a0, VecF& a1,
                                  VecF& a2, VecF& a3, VecF& b0, VecF& b1, VecF& b2, VecF& b3) {
    a0 = load(o), a1 = load(o + sx), a2 = load(o + sy), a3 = load(o + sx + sy);
    b0 = load(o + sz), b1 = load(o + sz + sx), b2 = load(o + sz + sy), b3 = load(o + sz + sx + sy);
}
// The field at the samples at o displaced by p (steps: commonSteps(p)).
OBSCURA_SMOKE_INLINE VecF sampleVec(const float* o, const Dims& d, VecF px, VecF py, VecF pz, const Steps& st) {
    if (!st.common) return kernels::sampleNearT(o, d, px, py, pz);
    VecF a0, a1, a2, a3, b0, b1, b2, b3;
    blockAt(o, st.x, st.y, st.z, a0, a1, a2, a3, b0, b1, b2, b3);
    return kernels::blendBlock(a0, a1, a2, a3, b0, b1, b2, b3, kernels::absT(px), kernels::absT(py), kernels::absT(pz));
}
// The range of the block at o for the displacement p (steps: commonSteps(p)).
OBSCURA_SMOKE_INLINE void rangeVec(const float* o, const Dims& d, VecF px, VecF py, VecF pz, const Steps& st, VecF& lo, VecF& hi) {
    if (!st.common) return kernels::rangeNearT(o, d, px, py, pz, lo, hi);
    VecF a0, a1, a2, a3, b0, b1, b2, b3;
    blockAt(o, st.x, st.y, st.z, a0, a1, a2, a3, b0, b1, b2, b3);
    lo = kernels::blockMin(a0, a1, a2, a3, b0, b1, b2, b3);
    hi = kernels::blockMax(a0, a1, a2, a3, b0, b1, b2, b3);
}

// Runs fn(i) for vectors covering [i0, i1): the last one is moved back to end at i1, so it
// recomputes a few lanes of the one before it (same inputs, same values). Rows are at least
// kLanes long (grids are 16 or more cells wide: SmokeSettings::resolution).
template <class Fn>
OBSCURA_SMOKE_INLINE void forVectors(int i0, int i1, const Fn& fn) {
    for (int i = i0; i < i1; i += kLanes) fn(std::min(i, i1 - kLanes));
}

// The semi-Lagrangian step: each sample from the block at -q.
void forwardRow(const float* f, float* hat, Trace q, Dims d, std::ptrdiff_t row, int i0, int i1) {
    forVectors(i0, i1, [&](int i) {
        const VecF px = -load(q.x + i), py = -load(q.y + i), pz = -load(q.z + i);
        store(hat + row + i, sampleVec(f + row + i, d, px, py, pz, commonSteps(px, py, pz, d)));
    });
}

// MacCormack: the reverse sample from hat's block at +q, the clamp range from f's block at -q
// (the same steps mirrored), times the dissipation factor.
void correctRow(const float* f, const float* hat, float* out, Trace q, Dims d, float decay, std::ptrdiff_t row, int i0, int i1) {
    forVectors(i0, i1, [&](int i) {
        const std::ptrdiff_t c = row + i;
        const VecF qx = load(q.x + i), qy = load(q.y + i), qz = load(q.z + i);
        const Steps forward = commonSteps(qx, qy, qz, d);
        const Steps back{forward.common, -forward.x, -forward.y, -forward.z};
        const VecF reverse = sampleVec(hat + c, d, qx, qy, qz, forward);
        const VecF value = kernels::macCormackValue(load(hat + c), load(f + c), reverse);
        VecF lo, hi;
        rangeVec(f + c, d, -qx, -qy, -qz, back, lo, hi);
        store(out + c, kernels::clampT(value, lo, hi) * decay);
    });
}

// Per-plane scratch: three trace rows (SmokeState::rowScratch).
Trace traceScratch(float* plane, int nx) { return {plane, plane + nx, plane + 2 * nx}; }

void advectForwardRow(Velocity f, VelocityOut hat, Dims d, float s, std::ptrdiff_t row, int i0, int i1, float* scratch) {
    using namespace kernels;
    const Trace q = traceScratch(scratch, d.nx);
    traceRow<kAtU>(f.u, f.v, f.w, d, s, row, i0, i1, q);
    forwardRow(f.u, hat.u, q, d, row, i0, i1);
    traceRow<kAtV>(f.u, f.v, f.w, d, s, row, i0, i1, q);
    forwardRow(f.v, hat.v, q, d, row, i0, i1);
    traceRow<kAtW>(f.u, f.v, f.w, d, s, row, i0, i1, q);
    forwardRow(f.w, hat.w, q, d, row, i0, i1);
}

void advectCorrectRow(Velocity f, Velocity hat, VelocityOut out, Dims d, float s, float decayV, std::ptrdiff_t row, int i0,
                      int i1, float* scratch) {
    using namespace kernels;
    const Trace q = traceScratch(scratch, d.nx);
    traceRow<kAtU>(f.u, f.v, f.w, d, s, row, i0, i1, q);
    correctRow(f.u, hat.u, out.u, q, d, decayV, row, i0, i1);
    traceRow<kAtV>(f.u, f.v, f.w, d, s, row, i0, i1, q);
    correctRow(f.v, hat.v, out.v, q, d, decayV, row, i0, i1);
    traceRow<kAtW>(f.u, f.v, f.w, d, s, row, i0, i1, q);
    correctRow(f.w, hat.w, out.w, q, d, decayV, row, i0, i1);
}

// ---- Flux-form transport of density and temperature (kernels::faceFluxes) ----
struct Masks3 {
    const std::uint8_t *u, *v, *w;
};

OBSCURA_SMOKE_INLINE VecI maskLoad(const std::uint8_t* p) {  // all ones where p[l] != 0
    VecI m;
    for (int l = 0; l < kLanes; ++l) m[l] = p[l] != 0 ? -1 : 0;
    return m;
}
OBSCURA_SMOKE_INLINE VecI fluidLoad(const std::uint8_t* cls) {  // all ones for fluid cells
    VecI m;
    for (int l = 0; l < kLanes; ++l) m[l] = cls[l] == kFluid ? -1 : 0;
    return m;
}

// Each cell's outflow cap for a step of dt into `cap` (kernels::outflowCapT); returns the row's
// largest outflow rate.
float outflowRow(const float* u, const float* v, const float* w, Masks3 m, const std::uint8_t* cls, float* cap, Dims d,
                 float invH, float dt, std::ptrdiff_t row, int i0, int i1) {
    VecF worst{};
    forVectors(i0, i1, [&](int i) {
        const std::ptrdiff_t c = row + i, y = c + d.sy, z = c + d.sz;
        const VecF r = kernels::outflowRateT(load(u + c), load(u + c + 1), load(v + c), load(v + y), load(w + c), load(w + z),
                                             maskLoad(m.u + c), maskLoad(m.u + c + 1), maskLoad(m.v + c), maskLoad(m.v + y),
                                             maskLoad(m.w + c), maskLoad(m.w + z), fluidLoad(cls + c), VecF{} + invH);
        store(cap + c, kernels::outflowCapT(r, dt));
        worst = kernels::maxT(worst, r);
    });
    float most = 0.f;
    for (int l = 0; l < kLanes; ++l) most = std::max(most, worst[l]);
    return most;
}

// One row of faces along one axis. Every pointer is at the row's start shifted to the stencil
// slot: the face's own velocity and mask; the masks of the faces below and above; the outflow
// cap of the cells below (b) and above (d); each scalar at a, b, d, e (see kernels::faceFluxes).
struct FaceRow {
    const float* vel;
    const std::uint8_t *open, *openLo, *openHi;
    const float *capB, *capD;
    const float *da, *db, *dd, *de, *ta, *tb, *td, *te;
    float *outD, *outT;
};
void fluxRow(FaceRow f, float courantPerSpeed, int i0, int i1) {
    forVectors(i0, i1, [&](int i) {
        VecF fd, ft;
        kernels::faceFluxesT(load(f.vel + i) * courantPerSpeed, maskLoad(f.open + i), maskLoad(f.openLo + i), maskLoad(f.openHi + i),
                             load(f.capB + i), load(f.capD + i), load(f.da + i), load(f.db + i), load(f.dd + i), load(f.de + i),
                             load(f.ta + i), load(f.tb + i), load(f.td + i), load(f.te + i), fd, ft);
        store(f.outD + i, fd);
        store(f.outT + i, ft);
    });
}

// The row of lower faces on `axis` of the cells in row (j, k), for fluxRow. The z faces of the
// first interior plane and of the top ghost plane have no cell two below / one above inside the
// array: those slots take the face cell's own (their values never count: a missing behind-cell
// only feeds the slope of a ghost donor, which holds 0).
FaceRow faceRow(SmokeState& s, int axis, int j, int k) {
    const Dims d = s.dims;
    const std::ptrdiff_t stride = axis == 0 ? 1 : axis == 1 ? d.sy : d.sz;
    const std::ptrdiff_t row = d.sy * j + d.sz * k;
    const bool bottom = axis == 2 && k == 1, top = axis == 2 && k == d.nz - 1;
    const std::ptrdiff_t a = bottom ? -stride : -2 * stride, e = top ? 0 : stride;
    const std::vector<std::uint8_t>& m = s.faceMask[axis];
    const std::vector<float>& vel = axis == 0 ? s.u : axis == 1 ? s.v : s.w;
    const float *D = s.density.data() + row, *T = s.temperature.data() + row, *R = s.outflow.data() + row;
    return {vel.data() + row,         m.data() + row,   m.data() + row - stride, m.data() + row + (top ? 0 : stride),
            R - stride,               R,                D + a,                   D - stride,
            D,                        D + e,            T + a,                   T - stride,
            T,                        T + e,            s.flux[0][axis].data() + row, s.flux[1][axis].data() + row};
}

void updateRow(const float* f, const float* fx, const float* fy, const float* fz, float* out, Dims d, float decay,
               std::ptrdiff_t row, int i0, int i1) {
#pragma omp simd
    for (int i = i0; i < i1; ++i) {
        const std::ptrdiff_t c = row + i;
        out[c] = kernels::fluxUpdate(f[c], fx[c], fx[c + 1], fy[c], fy[c + d.sy], fz[c], fz[c + d.sz], decay);
    }
}

void curlRow(const float* u, const float* v, const float* w, float* ox, float* oy, float* oz, float* mag, Dims d,
             float halfInvH, std::ptrdiff_t row, int i0, int i1) {
#pragma omp simd
    for (int i = i0; i < i1; ++i) {
        const std::ptrdiff_t c = row + i;
        float x, y, z;
        kernels::curlAt(u, v, w, c, d, halfInvH, x, y, z);
        ox[c] = x;
        oy[c] = y;
        oz[c] = z;
        mag[c] = kernels::magnitude(x, y, z);
    }
}

void confinementRow(float* ox, float* oy, float* oz, const float* mag, Dims d, float halfInvH, float epsH,
                    std::ptrdiff_t row, int i0, int i1) {
#pragma omp simd
    for (int i = i0; i < i1; ++i) {
        const std::ptrdiff_t c = row + i;
        float fx, fy, fz;
        kernels::confinementAt(mag, c, d, halfInvH, epsH, ox[c], oy[c], oz[c], fx, fy, fz);
        ox[c] = fx;
        oy[c] = fy;
        oz[c] = fz;
    }
}

void forcesRow(float* u, float* v, float* w, const float* ox, const float* oy, const float* oz, const float* T,
               const float* D, Masks3 m, Dims d, float dt, float buoy, float weight, float vmax, std::ptrdiff_t row, int i0,
               int i1) {
    const std::uint8_t *mu = m.u, *mv = m.v, *mw = m.w;
#pragma omp simd
    for (int i = i0; i < i1; ++i) {
        const std::ptrdiff_t c = row + i, b = c - d.sy;
        const float fu = kernels::forcedFace(u[c], ox[c - 1], ox[c], dt, vmax);
        const float fv = kernels::forcedFace(v[c], kernels::cellLift(oy[b], T[b], D[b], buoy, weight),
                                             kernels::cellLift(oy[c], T[c], D[c], buoy, weight), dt, vmax);
        const float fw = kernels::forcedFace(w[c], oz[c - d.sz], oz[c], dt, vmax);
        u[c] = kernels::sel(mu[c] != 0, fu, 0.f);
        v[c] = kernels::sel(mv[c] != 0, fv, 0.f);
        w[c] = kernels::sel(mw[c] != 0, fw, 0.f);
    }
}

// Each fluid cell's outflow cap for a step of dt into s.outflow; returns the largest outflow rate.
float outflowCaps(SmokeState& s, ThreadPool& pool, float dt) {
    const Dims d = s.dims;
    const Masks3 m{s.faceMask[0].data(), s.faceMask[1].data(), s.faceMask[2].data()};
    const float invH = 1.f / static_cast<float>(s.grid.cellSize);
    forPlanes(pool, 1, d.nz - 1, [&](int k) {
        float worst = 0.f;
        for (int j = 1; j < d.ny - 1; ++j)
            worst = std::max(worst, outflowRow(s.u.data(), s.v.data(), s.w.data(), m, s.cellClass.data(), s.outflow.data(), d, invH,
                                               dt, d.sy * j + d.sz * k, 1, d.nx - 1));
        s.planeA[static_cast<std::size_t>(k)] = worst;
    });
    float worst = 0.f;
    for (int k = 1; k < d.nz - 1; ++k) worst = std::max(worst, s.planeA[static_cast<std::size_t>(k)]);
    return worst;
}

void advect(SmokeState& s, ThreadPool& pool, float dt, float decayD, float decayT, float decayV) {
    const Dims d = s.dims;
    const float scale = dt / static_cast<float>(s.grid.cellSize);
    const Velocity f{s.u.data(), s.v.data(), s.w.data()};
    const VelocityOut hat{s.velHat[0].data(), s.velHat[1].data(), s.velHat[2].data()};
    const Velocity hatIn{hat.u, hat.v, hat.w};
    const VelocityOut out{s.next[2].data(), s.next[3].data(), s.next[4].data()};

    outflowCaps(s, pool, dt);
    // Pass 1: the scalars' face fluxes (x and y faces of the interior planes, z faces up to the
    // top ghost plane's) and the velocity's semi-Lagrangian forward step.
    forPlanes(pool, 1, d.nz, [&](int k) {
        for (int j = 1; j < d.ny - 1; ++j) fluxRow(faceRow(s, 2, j, k), scale, 1, d.nx - 1);
        if (k == d.nz - 1) return;
        float* scratch = s.rowScratch.data() + SmokeState::kScratchRows * static_cast<std::size_t>(d.nx) * k;  // this plane's own
        for (int j = 1; j < d.ny - 1; ++j) fluxRow(faceRow(s, 0, j, k), scale, 1, d.nx);
        for (int j = 1; j < d.ny; ++j) fluxRow(faceRow(s, 1, j, k), scale, 1, d.nx - 1);
        for (int j = 1; j < d.ny - 1; ++j) advectForwardRow(f, hat, d, scale, d.sy * j + d.sz * k, 1, d.nx - 1, scratch);
    });
    // Pass 2: the scalars from their fluxes (with the modelled decays), the velocity's MacCormack
    // correction and clamp.
    forPlanes(pool, 1, d.nz - 1, [&](int k) {
        float* scratch = s.rowScratch.data() + SmokeState::kScratchRows * static_cast<std::size_t>(d.nx) * k;
        for (int j = 1; j < d.ny - 1; ++j) {
            const std::ptrdiff_t row = d.sy * j + d.sz * k;
            updateRow(s.density.data(), s.flux[0][0].data(), s.flux[0][1].data(), s.flux[0][2].data(), s.next[0].data(), d, decayD,
                      row, 1, d.nx - 1);
            updateRow(s.temperature.data(), s.flux[1][0].data(), s.flux[1][1].data(), s.flux[1][2].data(), s.next[1].data(), d,
                      decayT, row, 1, d.nx - 1);
            advectCorrectRow(f, hatIn, out, d, scale, decayV, row, 1, d.nx - 1, scratch);
        }
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
            for (int j = 2; j < d.ny - 2; ++j) curlRow(u, v, w, ox, oy, oz, mag, d, halfInvH, d.sy * j + d.sz * k, 2, d.nx - 2);
        });
        // The force overwrites omega in place: each cell reads only its own omega and |omega| around.
        forPlanes(pool, 2, d.nz - 2, [&](int k) {
            for (int j = 2; j < d.ny - 2; ++j) confinementRow(ox, oy, oz, mag, d, halfInvH, epsH, d.sy * j + d.sz * k, 2, d.nx - 2);
        });
    }
    const float buoy = static_cast<float>(st.buoyancy), weight = static_cast<float>(st.densityWeight);
    const float vmax = static_cast<float>(st.maxSpeed);
    const Masks3 m{s.faceMask[0].data(), s.faceMask[1].data(), s.faceMask[2].data()};
    const float *T = s.temperature.data(), *D = s.density.data();
    forPlanes(pool, 1, d.nz - 1, [&](int k) {
        for (int j = 1; j < d.ny - 1; ++j)
            forcesRow(u, v, w, ox, oy, oz, T, D, m, d, dt, buoy, weight, vmax, d.sy * j + d.sz * k, 1, d.nx - 1);
    });
}

float divergenceRow(const float* u, const float* v, const float* w, const float* src, const std::uint8_t* cls, float* rhs,
                    Dims d, float invH, float h2, float emitFactor, std::ptrdiff_t row, int i0, int i1) {
    float maxDiv = 0.f;
#pragma omp simd reduction(max : maxDiv)
    for (int i = i0; i < i1; ++i) {
        const std::ptrdiff_t c = row + i;
        const float div = kernels::divergenceAt(u, v, w, c, d, invH);
        const bool fluid = cls[c] == kFluid;
        const float source = src[c] * emitFactor;
        maxDiv = std::max(maxDiv, kernels::sel(fluid, kernels::absf(div - source), 0.f));
        rhs[c] = kernels::sel(fluid, kernels::pressureRhs(div, source, h2), 0.f);
    }
    return maxDiv;
}

// Red-black layout (see SmokeState::rbPressure): row r's cell i of colour (i + j + k) & 1 sits at
// r * hx + (i >> 1) of that colour's array. Splitting a natural row into its two colours:
void splitRow(const float* natural, float* even, float* odd, int nx) {
    // even: cells 0, 2, 4, ...; odd: cells 1, 3, ... (a colour is even or odd by the row's parity)
    const int pairs = nx / 2;
#pragma omp simd
    for (int m = 0; m < pairs; ++m) {
        even[m] = natural[2 * m];
        odd[m] = natural[2 * m + 1];
    }
    if (nx & 1) {
        even[pairs] = natural[nx - 1];
        odd[pairs] = 0.f;
    }
}
void mergeRow(float* natural, const float* even, const float* odd, int nx) {
    const int pairs = nx / 2;
#pragma omp simd
    for (int m = 0; m < pairs; ++m) {
        natural[2 * m] = even[m];
        natural[2 * m + 1] = odd[m];
    }
    if (nx & 1) natural[nx - 1] = even[pairs];
}

// One colour's sweep on row (j, k): its cells i = 2m + e read only the other colour, which holds
// the x neighbours at m - 1 + e and m + e of the same row and the y / z neighbours at m of the
// rows around. Same sum order as kernels::neighbourSum, so the same bits as the natural layout.
void gaussSeidelRow(float* p, const float* other, const float* rhs, const float* dinv, std::ptrdiff_t row,
                    std::ptrdiff_t rowY, std::ptrdiff_t rowZ, int e, int m0, int m1) {
#pragma omp simd
    for (int m = m0; m <= m1; ++m) {
        const std::ptrdiff_t c = row + m, x = c - 1 + e;
        const float sum = ((((other[x] + other[x + 1]) + other[c - rowY]) + other[c + rowY]) + other[c - rowZ]) + other[c + rowZ];
        p[c] = kernels::pressureUpdate(sum, rhs[c], dinv[c]);
    }
}

void redBlackGaussSeidel(SmokeState& s, ThreadPool& pool, int iterations) {
    const Dims d = s.dims;
    const int hx = s.rbWidth();
    const std::ptrdiff_t rowY = hx, rowZ = static_cast<std::ptrdiff_t>(hx) * d.ny;
    auto split = [&](const std::vector<float>& natural, std::vector<float>* colours) {
        forPlanes(pool, 0, d.nz, [&](int k) {
            for (int j = 0; j < d.ny; ++j) {
                const int o = (j + k) & 1;  // the colour of the row's even cells
                const std::ptrdiff_t r = (static_cast<std::ptrdiff_t>(j) + static_cast<std::ptrdiff_t>(d.ny) * k) * hx;
                splitRow(natural.data() + d.sy * j + d.sz * k, colours[o].data() + r, colours[o ^ 1].data() + r, d.nx);
            }
        });
    };
    split(s.pressure, s.rbPressure);
    split(s.rhs, s.rbRhs);
    split(s.diagInv, s.rbDiagInv);
    for (int it = 0; it < iterations; ++it)
        for (int colour = 0; colour < 2; ++colour) {
            float* p = s.rbPressure[colour].data();
            const float* other = s.rbPressure[colour ^ 1].data();
            const float *rhs = s.rbRhs[colour].data(), *dinv = s.rbDiagInv[colour].data();
            forPlanes(pool, 1, d.nz - 1, [&](int k) {
                for (int j = 1; j < d.ny - 1; ++j) {
                    const int e = colour ^ ((j + k) & 1);  // this colour's cells are i = 2m + e
                    const std::ptrdiff_t r = (static_cast<std::ptrdiff_t>(j) + static_cast<std::ptrdiff_t>(d.ny) * k) * hx;
                    gaussSeidelRow(p, other, rhs, dinv, r, rowY, rowZ, e, 1 - e, (d.nx - 2 - e) >> 1);
                }
            });
        }
    forPlanes(pool, 0, d.nz, [&](int k) {
        for (int j = 0; j < d.ny; ++j) {
            const int o = (j + k) & 1;
            const std::ptrdiff_t r = (static_cast<std::ptrdiff_t>(j) + static_cast<std::ptrdiff_t>(d.ny) * k) * hx;
            mergeRow(s.pressure.data() + d.sy * j + d.sz * k, s.rbPressure[o].data() + r, s.rbPressure[o ^ 1].data() + r, d.nx);
        }
    });
}

void jacobiRow(const float* p, float* q, const float* rhs, const float* dinv, Dims d, std::ptrdiff_t row, int i0, int i1) {
#pragma omp simd
    for (int i = i0; i < i1; ++i) {
        const std::ptrdiff_t c = row + i;
        q[c] = kernels::pressureUpdate(kernels::neighbourSum(p, c, d), rhs[c], dinv[c]);
    }
}

float gradientRow(float* u, float* v, float* w, const float* p, const float* rhs, const float* dinv, Masks3 m, Dims d,
                  float invH, float invH2, std::ptrdiff_t row, int i0, int i1) {
    const std::uint8_t *mu = m.u, *mv = m.v, *mw = m.w;
    float maxRes = 0.f;
#pragma omp simd reduction(max : maxRes)
    for (int i = i0; i < i1; ++i) {
        const std::ptrdiff_t c = row + i;
        const float pu = kernels::projectedFace(u[c], p[c], p[c - 1], invH);
        const float pv = kernels::projectedFace(v[c], p[c], p[c - d.sy], invH);
        const float pw = kernels::projectedFace(w[c], p[c], p[c - d.sz], invH);
        u[c] = kernels::sel(mu[c] != 0, pu, 0.f);
        v[c] = kernels::sel(mv[c] != 0, pv, 0.f);
        w[c] = kernels::sel(mw[c] != 0, pw, 0.f);
        // What the projection leaves: (sum p_nb + rhs - n p) / h^2 (fluid cells: dinv > 0).
        const bool fluid = dinv[c] > 0.f;
        const float n = 1.f / kernels::sel(fluid, dinv[c], 1.f);
        const float r = kernels::absf(kernels::neighbourSum(p, c, d) + rhs[c] - p[c] * n) * invH2;
        maxRes = std::max(maxRes, kernels::sel(fluid, r, 0.f));
    }
    return maxRes;
}

// The multigrid levels' passes on the pool; levels of few planes run on the calling thread (a
// job's hand-off costs a few microseconds, about what such a level's pass takes).
#include "smoke/smoke_multigrid_ops.h"
struct PoolRunner {
    ThreadPool* pool;
    template <class Fn>
    void operator()(int k0, int k1, const Fn& fn) const {
        constexpr int kMinPoolPlanes = 12;
        if (k1 - k0 < kMinPoolPlanes) {
            for (int k = k0; k < k1; ++k) fn(k);
            return;
        }
        forPlanes(*pool, k0, k1, fn);
    }
};

// Right-hand side, then the pressure solve; returns the solver's iterations.
int project(SmokeState& s, const SmokeSettings& st, ThreadPool& pool, float emitFactor) {
    const Dims d = s.dims;
    const float h = static_cast<float>(s.grid.cellSize), invH = 1.f / h, h2 = h * h;
    const float *u = s.u.data(), *v = s.v.data(), *w = s.w.data(), *src = s.source.data(), *dinv = s.diagInv.data();
    const std::uint8_t* cls = s.cellClass.data();
    float* rhs = s.rhs.data();
    forPlanes(pool, 1, d.nz - 1, [&](int k) {
        float maxDiv = 0.f;
        for (int j = 1; j < d.ny - 1; ++j)
            maxDiv = std::max(maxDiv, divergenceRow(u, v, w, src, cls, rhs, d, invH, h2, emitFactor, d.sy * j + d.sz * k, 1, d.nx - 1));
        s.planeA[static_cast<std::size_t>(k)] = maxDiv;
    });

    if (st.pressureSolver == PressureSolver::MultigridCG) return mgops::solve(s, st, PoolRunner{&pool}).iterations;
    const int iterations = std::max(0, st.pressureIterations);
    if (st.pressureSolver == PressureSolver::RedBlackGaussSeidel) {
        redBlackGaussSeidel(s, pool, iterations);
    } else {
        for (int it = 0; it < iterations; ++it) {
            const float* p = s.pressure.data();
            float* q = s.pressureTmp.data();
            forPlanes(pool, 1, d.nz - 1, [&](int k) {
                for (int j = 1; j < d.ny - 1; ++j) jacobiRow(p, q, rhs, dinv, d, d.sy * j + d.sz * k, 1, d.nx - 1);
            });
            std::swap(s.pressure, s.pressureTmp);
        }
    }
    return iterations;
}

void subtractGradient(SmokeState& s, ThreadPool& pool) {
    const Dims d = s.dims;
    const float h = static_cast<float>(s.grid.cellSize), invH = 1.f / h, invH2 = 1.f / (h * h);
    float *u = s.u.data(), *v = s.v.data(), *w = s.w.data();
    const float *p = s.pressure.data(), *rhs = s.rhs.data(), *dinv = s.diagInv.data();
    const Masks3 m{s.faceMask[0].data(), s.faceMask[1].data(), s.faceMask[2].data()};
    forPlanes(pool, 1, d.nz - 1, [&](int k) {
        float maxRes = 0.f;
        for (int j = 1; j < d.ny - 1; ++j)
            maxRes = std::max(maxRes, gradientRow(u, v, w, p, rhs, dinv, m, d, invH, invH2, d.sy * j + d.sz * k, 1, d.nx - 1));
        s.planeB[static_cast<std::size_t>(k)] = maxRes;
    });
}

}  // namespace

void substepFastImpl(SmokeState& s, const SmokeSettings& st, ThreadPool& pool, float dt) {
    using Clock = std::chrono::steady_clock;
    auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
    const auto t0 = Clock::now();
    applyEmitter(s, st, dt);
    const float decayD = densityDecay(s, st, dt);
    const float decayT = static_cast<float>(std::exp(-st.temperatureDissipation * dt));
    const float decayV = static_cast<float>(std::exp(-st.velocityDissipation * dt));
    advect(s, pool, dt, decayD, decayT, decayV);
    setBorderFaces(s);  // the curl reads the border faces: give them this step's values
    const auto t1 = Clock::now();
    forces(s, st, pool, dt);
    setBorderFaces(s);
    patchDynamicFaces(s);
    const auto t2 = Clock::now();
    const float emitFactor = s.age < st.emitTime ? 1.f : 0.f;
    s.projectedSource = emitFactor;
    const int iterations = project(s, st, pool, emitFactor);
    const auto t3 = Clock::now();
    subtractGradient(s, pool);
    projectBorderFaces(s);
    patchDynamicFaces(s);
    const auto t4 = Clock::now();
    s.stats.msAdvect += ms(t0, t1);
    s.stats.msForces += ms(t1, t2);
    s.stats.msPressure += ms(t2, t3);
    s.stats.msProject += ms(t3, t4);
    float before = 0, after = 0;
    for (int k = 1; k < s.grid.nz - 1; ++k) {
        before = std::max(before, s.planeA[static_cast<std::size_t>(k)]);
        after = std::max(after, s.planeB[static_cast<std::size_t>(k)]);
    }
    recordProjection(s.stats, before, after, iterations, st.pressureAbsoluteTolerance);
}

float maxOutflowRateImpl(SmokeState& s, ThreadPool& pool) { return outflowCaps(s, pool, 0.f); }
PressureSolveStats solvePressureImpl(SmokeState& s, const SmokeSettings& st, ThreadPool& pool) {
    return mgops::solve(s, st, PoolRunner{&pool});
}
