// The multigrid hierarchy's construction (see smoke_multigrid.h).
#include "smoke/smoke_multigrid.h"

#include <algorithm>
#include <cmath>

#include "smoke/smoke_state.h"

namespace obscura::smoke {
namespace {

kernels::Dims padded(int interior) {
    const int n = interior + 2;
    return {n, n, n, static_cast<std::ptrdiff_t>(n), static_cast<std::ptrdiff_t>(n) * n};
}

// Level 0's face coefficient: 1 between two fluid cells (both unknowns), else 0 (a solid face
// drops out; a face to an open cell is Dirichlet and only counts in the diagonal).
float fineCoef(const std::vector<std::uint8_t>& cls, std::size_t a, std::size_t b) {
    return cls[a] == kFluid && cls[b] == kFluid ? 1.f : 0.f;
}

// Level l + 1's planes [K0, K1] from level l (l == 0: coefficients from the cell classes).
void coarsen(const SmokeState& s, const MgLevel& f, MgLevel& c, int l, int K0, int K1) {
    const auto& fd = f.dims;
    const auto& cd = c.dims;
    const std::vector<std::uint8_t>& cls = s.cellClass;
    const std::ptrdiff_t fsy = fd.sy, fsz = fd.sz;
    auto coef = [&](int axis, std::size_t n) -> float {  // fine coefficient of n's lower face
        if (l > 0) return axis == 0 ? f.cx[n] : axis == 1 ? f.cy[n] : f.cz[n];
        const std::size_t stride = axis == 0 ? 1 : axis == 1 ? static_cast<std::size_t>(fsy) : static_cast<std::size_t>(fsz);
        return fineCoef(cls, n - stride, n);
    };
    for (int K = std::max(1, K0); K <= std::min(cd.nz - 2, K1); ++K)
        for (int J = 1; J <= cd.ny - 2; ++J)
            for (int I = 1; I <= cd.nx - 2; ++I) {
                const std::size_t C = static_cast<std::size_t>(I + cd.sy * J + cd.sz * K);
                const std::size_t f0 = static_cast<std::size_t>((2 * I - 1) + fsy * (2 * J - 1) + fsz * (2 * K - 1));
                float diagSum = 0.f, internal = 0.f, lower[3] = {0.f, 0.f, 0.f};
                for (int dk = 0; dk < 2; ++dk)
                    for (int dj = 0; dj < 2; ++dj)
                        for (int di = 0; di < 2; ++di) {
                            const std::size_t n = f0 + static_cast<std::size_t>(di + fsy * dj + fsz * dk);
                            diagSum += f.diag[n];
                            // Each child's lower face is internal (second child on that axis) or
                            // the coarse cell's lower face (first child).
                            const int side[3] = {di, dj, dk};
                            for (int a = 0; a < 3; ++a) (side[a] ? internal : lower[a]) += coef(a, n);
                        }
                c.diag[C] = 0.5f * (diagSum - 2.f * internal);
                c.dinv[C] = c.diag[C] > 0.f ? 1.f / c.diag[C] : 0.f;
                c.cx[C] = 0.5f * lower[0];
                c.cy[C] = 0.5f * lower[1];
                c.cz[C] = 0.5f * lower[2];
            }
}

void level0Diagonal(SmokeState& s, int k0, int k1) {
    MgLevel& L = s.mg.levels[0];
    const std::size_t b = static_cast<std::size_t>(L.dims.sz) * static_cast<std::size_t>(std::max(0, k0));
    const std::size_t e = static_cast<std::size_t>(L.dims.sz) * static_cast<std::size_t>(std::min(L.dims.nz - 1, k1) + 1);
    for (std::size_t c = b; c < e; ++c) L.diag[c] = s.diagInv[c] > 0.f ? std::round(1.f / s.diagInv[c]) : 0.f;  // the neighbour count
}

void coarsenRange(SmokeState& s, int k0, int k1) {
    auto& levels = s.mg.levels;
    for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
        // Coarse plane K holds fine planes 2K - 1, 2K and reads the fine faces below 2K - 1.
        const int K0 = k0 / 2, K1 = (k1 + 2) / 2;
        coarsen(s, levels[l], levels[l + 1], static_cast<int>(l), K0, K1);
        k0 = K0;
        k1 = K1;
    }
}

}  // namespace

void initialiseMultigrid(SmokeState& s) {
    Multigrid& mg = s.mg;
    mg.levels.clear();
    MgLevel fine;
    fine.dims = s.dims;
    fine.diag.assign(s.grid.cells(), 0.f);
    mg.levels.push_back(std::move(fine));
    int interior = s.grid.nx - 2;  // cubic grids (SmokeVolume::create)
    while (interior > mg::kCoarsestSize) {
        interior = (interior + 1) / 2;
        MgLevel c;
        c.dims = padded(interior);
        for (auto* v : {&c.diag, &c.dinv, &c.cx, &c.cy, &c.cz, &c.x, &c.b, &c.tmp}) v->assign(c.cells(), 0.f);
        mg.levels.push_back(std::move(c));
    }
    for (auto* v : {&mg.r, &mg.z, &mg.d, &mg.q, &mg.tmp}) v->assign(s.grid.cells(), 0.f);
    mg.planeSum.assign(static_cast<std::size_t>(s.grid.nz), 0.0);
    mg.planeMax.assign(static_cast<std::size_t>(s.grid.nz), 0.f);
    mg.planeMax2.assign(static_cast<std::size_t>(s.grid.nz), 0.f);
    updateMultigrid(s, 0, s.grid.nz - 1);
}

void updateMultigrid(SmokeState& s, int k0, int k1) {
    if (s.mg.levels.empty()) return;
    level0Diagonal(s, k0, k1);
    coarsenRange(s, k0, k1);
}

}  // namespace obscura::smoke
