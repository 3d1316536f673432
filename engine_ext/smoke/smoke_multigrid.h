// The pressure solve: conjugate gradients preconditioned by one multigrid V-cycle (McAdams, Sifakis,
// Teran, "A parallel multigrid Poisson solver for fluids simulation on large grids", SCA 2010).
// Internal to engine_ext/smoke.
//
// Levels: level 0 is the simulation grid (unknowns: the fluid cells; unit face coefficients between
// fluid cells; open ghost cells are Dirichlet p = 0, solid ones drop out). Each coarser level
// halves every axis; a coarse cell's unknown stands for its fluid children, and its operator is
// half the Galerkin product R A P with piecewise-constant P (R = P^T): the coefficient of a coarse
// face is half the sum of the fine coefficients across it. So a wall a cell thick that closes a
// coarse face keeps it closed on every level (the coarse grids do not couple the two sides of a
// thin wall), and in open space the coarse operator is the fine one rediscretised at 2h (the half
// undoes piecewise-constant Galerkin's known factor of two). Smoother: damped Jacobi, the same
// number of sweeps before and after (a symmetric V-cycle, as CG needs).
//
// Every level is padded: cells 1..n-2 on each axis are the unknowns' slots, the rest stay 0.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "smoke/smoke_kernels.h"

namespace obscura::smoke {

struct SmokeState;

struct MgLevel {
    kernels::Dims dims{};
    std::vector<float> diag, dinv;  // operator diagonal and its inverse (0: not an unknown)
    std::vector<float> cx, cy, cz;  // coefficients of each cell's lower x / y / z face (levels >= 1)
    std::vector<float> x, b, tmp;   // work (level 0 uses Multigrid's CG vectors instead)
    std::size_t cells() const { return static_cast<std::size_t>(dims.nx) * dims.ny * dims.nz; }
};

struct Multigrid {
    std::vector<MgLevel> levels;    // [0] = the simulation grid
    std::vector<float> r, z, d, q, tmp;  // CG on level 0: residual, preconditioned residual, direction, A d
    std::vector<double> planeSum;   // per z-plane partials of level 0 (fixed order)
    std::vector<float> planeMax, planeMax2;
};

// Sizes the hierarchy for the state's grid and builds every level from the state's cell classes.
void initialiseMultigrid(SmokeState& s);
// Rebuilds level 0's diagonal for planes [k0, k1] and the coarse levels above them (after the cell
// classes there changed: moving obstacles).
void updateMultigrid(SmokeState& s, int k0, int k1);

// Tuned constants, each with its reason (measured: README.md, "Pressure").
namespace mg {
// Tuned on 24 steps of a bloom on open floor (48^3) plus the closed doorway rooms (36^3), counting
// the solve's instructions (callgrind): sweeps 1 / 2 / 3 / 4 at damping 0.8 took 3.80 / 2.78 /
// 2.46 / - G, and at 0.9 with 8 coarsest sweeps 3 and 4 took 2.21 and 2.12 G (4 % for a fourth
// pass over memory: not worth it).
// Jacobi damping: stable below 1 for these diagonally dominant operators on every level; 0.9
// beat 0.8 by 8 % (the 7-point Laplacian's smoothing optimum is 6/7).
constexpr float kOmega = 0.9f;
// Sweeps before and after the coarse correction on every level but the coarsest.
constexpr int kSmooth = 3;
// Sweeps on the coarsest level (at most 4^3 cells): 8 and 24 converge alike.
constexpr int kCoarsestSweeps = 8;
// Coarsen while a level has more than this many unknowns' slots on an axis.
constexpr int kCoarsestSize = 4;
}  // namespace mg

// What a solve did.
struct PressureSolveStats {
    int iterations = 0;
    double initialResidual = 0;  // max |b - A p| before (rhs units: h^2 / s)
    double finalResidual = 0;    // the recursive residual's max at the end
    double rhsMax = 0;           // max |b|
};

// The MGPCG iteration and the V-cycle, written once for both paths; Ops does the grid passes
// (smoke_multigrid_impl.h: threads and vectors; smoke_solver_reference.cpp: plain loops), so the
// two paths run the same operations in the same order.
//   Ops: int levelCount(); void removeMean() (b); double centreZ() (z -= its mean, returns <r, z>);
//        void initialResidual(float& maxR, float& maxB);
//        void smoothFromZero(int l); void smooth(int l); double smoothDot(int l) (level 0: <r, z>);
//        void residualRestrict(int l); void prolong(int l); double applyDot() (q = A d, <d, q>);
//        float update(float alpha) (x += a d, r -= a q, max |r|); void copyDirection() (d = z);
//        void direction(float beta) (d = z + beta d).
template <class Ops>
double vcycle(Ops& ops, int level) {
    const int last = ops.levelCount() - 1;
    const int sweeps = level == last ? mg::kCoarsestSweeps : mg::kSmooth;
    ops.smoothFromZero(level);
    for (int i = 1; i < sweeps; ++i) ops.smooth(level);
    if (level == last) return 0.0;
    ops.residualRestrict(level);
    vcycle(ops, level + 1);
    ops.prolong(level);
    for (int i = 1; i < mg::kSmooth; ++i) ops.smooth(level);
    if (level > 0) {
        ops.smooth(level);
        return 0.0;
    }
    return ops.smoothDot(level);  // the last sweep on level 0 also gives <r, z>
}

// Solves A p = b from the warm start in p until max |r| <= relTol * max |b| or <= absTol, at most
// maxIterations. `closed`: the region has no Dirichlet cell, so A is singular (constants are its
// null space): b's mean is removed, and so is the preconditioned residual's after every V-cycle,
// which keeps CG in A's range (without it the coarse levels' sweeps feed float round-off into
// the constant, the pressure drifts by thousands and its differences lose their digits).
template <class Ops>
PressureSolveStats solveMgcg(Ops& ops, bool closed, double relTol, double absTol, int maxIterations) {
    PressureSolveStats st;
    auto precondition = [&]() {
        const double rz = vcycle(ops, 0);
        return closed ? ops.centreZ() : rz;
    };
    if (closed) ops.removeMean();
    float maxR = 0, maxB = 0;
    ops.initialResidual(maxR, maxB);
    st.initialResidual = st.finalResidual = maxR;
    st.rhsMax = maxB;
    const double target = std::max(absTol, relTol * static_cast<double>(maxB));
    if (!(maxR > target)) return st;  // also stops on NaN
    double rz = precondition();
    ops.copyDirection();
    for (int it = 1; it <= maxIterations; ++it) {
        const double dq = ops.applyDot();
        if (!(dq > 0) || !(rz > 0)) break;  // converged to round-off (or a NaN upstream)
        maxR = ops.update(static_cast<float>(rz / dq));
        st.iterations = it;
        st.finalResidual = maxR;
        if (!(maxR > target)) break;
        const double rzNew = precondition();
        ops.direction(static_cast<float>(rzNew / rz));
        rz = rzNew;
    }
    return st;
}

}  // namespace obscura::smoke
