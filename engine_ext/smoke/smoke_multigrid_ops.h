// The grid passes of the MultigridCG solve (smoke_multigrid.h's Ops), written once and included
// twice: by smoke_solver_fast.cpp inside each vector build's namespace (planes on the thread pool,
// `omp simd` rows) and by smoke_solver_reference.cpp (one thread, the same rows as plain scalar
// loops: that file is built without -fopenmp-simd). Not a standalone header: the includer provides
// <vector>, <algorithm>, <cmath>, smoke_state.h and the enclosing namespace. Every pass writes
// each cell from inputs of the pass before, and every sum goes through kernels::rowDot rows,
// per-plane double partials and a plane-order total, so neither the runner nor the vector width
// changes a bit.
namespace mgops {

using kernels::Dims;

// Row kernels (x in [1, nx - 2] of the row starting at index `row`). Arguments by value. The ones
// with a max reduction stay out of line: inlined into the plane loops, GCC 12 drops their
// `omp simd reduction` lane arrays and leaves them scalar.
#define OBSCURA_SMOKE_ROW_REDUCTION __attribute__((noinline))
inline void fromZeroRow(float* x, const float* b, const float* dinv, float omega, std::ptrdiff_t row, int n) {
OBSCURA_SMOKE_SIMD_LOOP
    for (int i = 1; i < n - 1; ++i) x[row + i] = kernels::jacobiFromZero(b[row + i], dinv[row + i], omega);
}
inline void jacobiFineRow(float* out, const float* x, const float* b, const float* dinv, Dims d, float omega, std::ptrdiff_t row) {
OBSCURA_SMOKE_SIMD_LOOP
    for (int i = 1; i < d.nx - 1; ++i) {
        const std::ptrdiff_t c = row + i;
        out[c] = kernels::jacobiStep(x[c], kernels::neighbourSum(x, c, d), b[c], dinv[c], omega);
    }
}
inline void jacobiCoarseRow(float* out, const float* x, const float* b, const float* dinv, const float* cx, const float* cy,
                            const float* cz, Dims d, float omega, std::ptrdiff_t row) {
OBSCURA_SMOKE_SIMD_LOOP
    for (int i = 1; i < d.nx - 1; ++i) {
        const std::ptrdiff_t c = row + i;
        out[c] = kernels::jacobiStep(x[c], kernels::coarseNeighbours(x, cx, cy, cz, c, d.sy, d.sz), b[c], dinv[c], omega);
    }
}
inline void residualFineRow(float* out, const float* x, const float* b, const float* diag, const float* dinv, Dims d,
                            std::ptrdiff_t row) {
OBSCURA_SMOKE_SIMD_LOOP
    for (int i = 1; i < d.nx - 1; ++i) {
        const std::ptrdiff_t c = row + i;
        out[c] = kernels::residualAt(b[c], diag[c], x[c], kernels::neighbourSum(x, c, d), dinv[c]);
    }
}
inline void residualCoarseRow(float* out, const float* x, const float* b, const float* diag, const float* dinv, const float* cx,
                              const float* cy, const float* cz, Dims d, std::ptrdiff_t row) {
OBSCURA_SMOKE_SIMD_LOOP
    for (int i = 1; i < d.nx - 1; ++i) {
        const std::ptrdiff_t c = row + i;
        out[c] = kernels::residualAt(b[c], diag[c], x[c], kernels::coarseNeighbours(x, cx, cy, cz, c, d.sy, d.sz), dinv[c]);
    }
}
// Coarse row (J, K) of b from the fine residual: each coarse cell sums its 8 children.
inline void restrictRow(float* bc, const float* rf, Dims cd, Dims fd, int J, int K) {
    const std::ptrdiff_t row = cd.sy * J + cd.sz * K, fine = fd.sy * (2 * J - 1) + fd.sz * (2 * K - 1);
OBSCURA_SMOKE_SIMD_LOOP
    for (int I = 1; I < cd.nx - 1; ++I) bc[row + I] = kernels::sum8(rf, fine + 2 * I - 1, fd.sy, fd.sz);
}
// Fine row (j, k) += its parents' values (unknowns only).
inline void prolongRow(float* xf, const float* xc, const float* dinv, Dims fd, Dims cd, int j, int k) {
    const std::ptrdiff_t row = fd.sy * j + fd.sz * k, parent = cd.sy * ((j + 1) >> 1) + cd.sz * ((k + 1) >> 1);
OBSCURA_SMOKE_SIMD_LOOP
    for (int i = 1; i < fd.nx - 1; ++i) {
        const std::ptrdiff_t c = row + i;
        xf[c] = kernels::sel(dinv[c] > 0.f, xf[c] + xc[parent + ((i + 1) >> 1)], xf[c]);
    }
}
inline void applyRow(float* q, const float* dir, const float* diag, const float* dinv, Dims d, std::ptrdiff_t row) {
OBSCURA_SMOKE_SIMD_LOOP
    for (int i = 1; i < d.nx - 1; ++i) {
        const std::ptrdiff_t c = row + i;
        q[c] = kernels::applyAt(diag[c], dir[c], kernels::neighbourSum(dir, c, d), dinv[c]);
    }
}
OBSCURA_SMOKE_ROW_REDUCTION inline float updateRow(float* x, float* r, const float* dir, const float* q, float alpha, std::ptrdiff_t row, int n) {
    float m = 0.f;
OBSCURA_SMOKE_SIMD_MAX_M
    for (int i = 1; i < n - 1; ++i) {
        const std::ptrdiff_t c = row + i;
        x[c] = x[c] + alpha * dir[c];
        r[c] = r[c] - alpha * q[c];
        m = std::max(m, kernels::absf(r[c]));
    }
    return m;
}
inline void directionRow(float* dir, const float* z, float beta, std::ptrdiff_t row, int n) {
OBSCURA_SMOKE_SIMD_LOOP
    for (int i = 1; i < n - 1; ++i) dir[row + i] = z[row + i] + beta * dir[row + i];
}
inline void copyRow(float* dst, const float* src, std::ptrdiff_t row, int n) {
OBSCURA_SMOKE_SIMD_LOOP
    for (int i = 1; i < n - 1; ++i) dst[row + i] = src[row + i];
}
OBSCURA_SMOKE_ROW_REDUCTION inline float maxAbsRow(const float* a, std::ptrdiff_t row, int n) {
    float m = 0.f;
OBSCURA_SMOKE_SIMD_MAX_M
    for (int i = 1; i < n - 1; ++i) m = std::max(m, kernels::absf(a[row + i]));
    return m;
}
inline int countRow(const float* dinv, std::ptrdiff_t row, int n) {
    int count = 0;
    for (int i = 1; i < n - 1; ++i) count += dinv[row + i] > 0.f;
    return count;
}
inline void subtractRow(float* b, const float* dinv, float mean, std::ptrdiff_t row, int n) {
OBSCURA_SMOKE_SIMD_LOOP
    for (int i = 1; i < n - 1; ++i) b[row + i] = kernels::sel(dinv[row + i] > 0.f, b[row + i] - mean, b[row + i]);
}
// A row of ones, for sums through rowDot (x * 1 == x exactly).
inline const float* ones(int n) {
    static const std::vector<float> one(1024, 1.f);  // rows are at most 128 + 2 cells
    return n <= 1024 ? one.data() : nullptr;
}

// Runner: void operator()(int k0, int k1, fn) calls fn(k) for k in [k0, k1) (threads or not).
template <class Runner>
struct Ops {
    SmokeState& s;
    Runner run;

    int levelCount() const { return static_cast<int>(s.mg.levels.size()); }
    MgLevel& L(int l) { return s.mg.levels[static_cast<std::size_t>(l)]; }
    const Dims& dims(int l) { return L(l).dims; }
    std::vector<float>& xv(int l) { return l == 0 ? s.mg.z : L(l).x; }
    std::vector<float>& tv(int l) { return l == 0 ? s.mg.tmp : L(l).tmp; }
    const float* b(int l) { return l == 0 ? s.mg.r.data() : L(l).b.data(); }
    const float* dinv(int l) { return l == 0 ? s.diagInv.data() : L(l).dinv.data(); }
    template <class Fn>
    void rows(int l, const Fn& fn) {  // fn(row index, j, k) over the level's interior rows
        const Dims d = dims(l);
        run(1, d.nz - 1, [&, d](int k) {
            for (int j = 1; j < d.ny - 1; ++j) fn(d.sy * j + d.sz * k, j, k);
        });
    }
    // Per-plane double partials of level 0 rows, summed in plane order.
    template <class Fn>
    double sumRows(const Fn& rowValue) {
        const Dims d = dims(0);
        std::vector<double>& part = s.mg.planeSum;
        run(1, d.nz - 1, [&, d](int k) {
            double sum = 0;
            for (int j = 1; j < d.ny - 1; ++j) sum += static_cast<double>(rowValue(d.sy * j + d.sz * k));
            part[static_cast<std::size_t>(k)] = sum;
        });
        double total = 0;
        for (int k = 1; k < d.nz - 1; ++k) total += part[static_cast<std::size_t>(k)];
        return total;
    }
    template <class Fn>
    float maxRows(std::vector<float>& part, const Fn& rowValue) {
        const Dims d = dims(0);
        run(1, d.nz - 1, [&, d](int k) {
            float m = 0.f;
            for (int j = 1; j < d.ny - 1; ++j) m = std::max(m, rowValue(d.sy * j + d.sz * k));
            part[static_cast<std::size_t>(k)] = m;
        });
        float m = 0.f;
        for (int k = 1; k < d.nz - 1; ++k) m = std::max(m, part[static_cast<std::size_t>(k)]);
        return m;
    }

    void smoothFromZero(int l) {
        float* x = xv(l).data();
        const float *bb = b(l), *di = dinv(l);
        const int n = dims(l).nx;
        rows(l, [&](std::ptrdiff_t row, int, int) { fromZeroRow(x, bb, di, mg::kOmega, row, n); });
    }
    void jacobiInto(int l) {  // tv(l) = one sweep of xv(l)
        const Dims d = dims(l);
        float* out = tv(l).data();
        const float *x = xv(l).data(), *bb = b(l), *di = dinv(l);
        if (l == 0) {
            rows(l, [&](std::ptrdiff_t row, int, int) { jacobiFineRow(out, x, bb, di, d, mg::kOmega, row); });
        } else {
            const float *cx = L(l).cx.data(), *cy = L(l).cy.data(), *cz = L(l).cz.data();
            rows(l, [&](std::ptrdiff_t row, int, int) { jacobiCoarseRow(out, x, bb, di, cx, cy, cz, d, mg::kOmega, row); });
        }
    }
    void smooth(int l) {
        jacobiInto(l);
        std::swap(xv(l), tv(l));
    }
    double smoothDot(int l) {  // level 0: a sweep, then <r, z>
        smooth(l);
        const float *r = s.mg.r.data(), *z = s.mg.z.data();
        const int n = dims(0).nx;
        return sumRows([&](std::ptrdiff_t row) { return kernels::rowDot(r + row, z + row, n); });
    }
    void residualRestrict(int l) {
        const Dims d = dims(l);
        float* res = tv(l).data();
        const float *x = xv(l).data(), *bb = b(l), *di = dinv(l), *dg = L(l).diag.data();
        if (l == 0) {
            rows(l, [&](std::ptrdiff_t row, int, int) { residualFineRow(res, x, bb, dg, di, d, row); });
        } else {
            const float *cx = L(l).cx.data(), *cy = L(l).cy.data(), *cz = L(l).cz.data();
            rows(l, [&](std::ptrdiff_t row, int, int) { residualCoarseRow(res, x, bb, dg, di, cx, cy, cz, d, row); });
        }
        float* bc = L(l + 1).b.data();
        const Dims cd = dims(l + 1);
        rows(l + 1, [&](std::ptrdiff_t, int J, int K) { restrictRow(bc, res, cd, d, J, K); });
    }
    void prolong(int l) {
        float* x = xv(l).data();
        const float *xc = xv(l + 1).data(), *di = dinv(l);
        const Dims fd = dims(l), cd = dims(l + 1);
        rows(l, [&](std::ptrdiff_t, int j, int k) { prolongRow(x, xc, di, fd, cd, j, k); });
    }

    // CG on level 0: x = s.pressure, b = s.rhs.
    double unknowns = 0;  // counted by removeMean
    // v -= its mean over the unknowns (closed regions: A's null space is the constants).
    void centre(float* v) {
        const Dims d = dims(0);
        const float *di = s.diagInv.data(), *one = ones(d.nx);
        if (!one || !(unknowns > 0)) return;
        const double sum = sumRows([&](std::ptrdiff_t row) { return kernels::rowDot(v + row, one, d.nx); });
        const float mean = static_cast<float>(sum / unknowns);
        rows(0, [&](std::ptrdiff_t row, int, int) { subtractRow(v, di, mean, row, d.nx); });
    }
    void removeMean() {
        const Dims d = dims(0);
        const float* di = s.diagInv.data();
        unknowns = sumRows([&](std::ptrdiff_t row) { return static_cast<float>(countRow(di, row, d.nx)); });
        centre(s.rhs.data());
    }
    double centreZ() {
        centre(s.mg.z.data());
        const float *r = s.mg.r.data(), *z = s.mg.z.data();
        const int n = dims(0).nx;
        return sumRows([&](std::ptrdiff_t row) { return kernels::rowDot(r + row, z + row, n); });
    }
    void initialResidual(float& maxR, float& maxB) {
        const Dims d = dims(0);
        float* r = s.mg.r.data();
        const float *x = s.pressure.data(), *bb = s.rhs.data(), *di = s.diagInv.data(), *dg = L(0).diag.data();
        rows(0, [&](std::ptrdiff_t row, int, int) { residualFineRow(r, x, bb, dg, di, d, row); });
        maxR = maxRows(s.mg.planeMax, [&](std::ptrdiff_t row) { return maxAbsRow(r, row, d.nx); });
        maxB = maxRows(s.mg.planeMax2, [&](std::ptrdiff_t row) { return maxAbsRow(bb, row, d.nx); });
    }
    double applyDot() {
        const Dims d = dims(0);
        float* q = s.mg.q.data();
        const float *dir = s.mg.d.data(), *di = s.diagInv.data(), *dg = L(0).diag.data();
        return sumRows([&](std::ptrdiff_t row) {
            applyRow(q, dir, dg, di, d, row);
            return kernels::rowDot(dir + row, q + row, d.nx);
        });
    }
    float update(float alpha) {
        const int n = dims(0).nx;
        float *x = s.pressure.data(), *r = s.mg.r.data();
        const float *dir = s.mg.d.data(), *q = s.mg.q.data();
        return maxRows(s.mg.planeMax, [&](std::ptrdiff_t row) { return updateRow(x, r, dir, q, alpha, row, n); });
    }
    void copyDirection() {
        const int n = dims(0).nx;
        float* dir = s.mg.d.data();
        const float* z = s.mg.z.data();
        rows(0, [&](std::ptrdiff_t row, int, int) { copyRow(dir, z, row, n); });
    }
    void direction(float beta) {
        const int n = dims(0).nx;
        float* dir = s.mg.d.data();
        const float* z = s.mg.z.data();
        rows(0, [&](std::ptrdiff_t row, int, int) { directionRow(dir, z, beta, row, n); });
    }
};

template <class Runner>
PressureSolveStats solve(SmokeState& s, const SmokeSettings& st, Runner run) {
    Ops<Runner> ops{s, run};
    const double h2 = s.grid.cellSize * s.grid.cellSize;
    return solveMgcg(ops, !s.regionOpen, st.pressureTolerance, st.pressureAbsoluteTolerance * h2,
                     std::max(0, st.pressureMaxIterations));
}

}  // namespace mgops
#undef OBSCURA_SMOKE_ROW_REDUCTION
