// The smoke solver's state (fields, cell classes, scratch) and the two stepping paths that update
// it: the optimised multithreaded one and the scalar reference. Internal to engine_ext/smoke and
// its tests; the game uses smoke_volume.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "smoke/smoke_grid.h"
#include "smoke/smoke_kernels.h"
#include "smoke/smoke_settings.h"

namespace obscura::smoke {

class ThreadPool;

// What the last step did (the last substep's figures where it was split).
struct SmokeStats {
    int substeps = 0;
    int pressureIterations = 0;
    double divergenceBefore = 0;  // max |div u| over fluid cells before the projection (1/s)
    double residual = 0;          // max |div u - source| left after it (1/s)
    double maxSpeed = 0;          // m/s, max |face velocity| after the step
    double milliseconds = 0;      // wall time of the whole step() call
    // Wall time per phase of the optimised path, summed over the step's substeps (ms).
    double msAdvect = 0, msForces = 0, msPressure = 0, msProject = 0;
};

struct DynamicCell {
    std::size_t index;
    float vx, vy, vz;  // the obstacle's velocity (m/s)
};

struct SmokeState {
    GridInfo grid;
    kernels::Dims dims{};
    std::vector<std::uint8_t> voxelSolid;   // the voxeliser's verdict: 0 free, kVoxelBuilt, kVoxelOutside
    std::vector<std::uint8_t> staticClass;  // CellClass: voxels + sealed-off fluid + the ghost layer
    std::vector<std::uint8_t> cellClass;    // staticClass + moving obstacles: what the solver uses
    std::vector<std::uint8_t> faceMask[3];  // 1: face between c - stride and c is between a fluid cell
                                            // and a non-solid one (projected); 0: boundary (set)
    std::vector<float> diagInv;             // 1 / non-solid neighbours for fluid cells, 0 elsewhere
    std::vector<float> source;              // volume source (1/s) per cell: the emitter's expansion
    std::vector<DynamicCell> dynamicCells;  // cells covered by moving obstacles this step

    // Fields (see smoke_kernels.h for the staggering).
    std::vector<float> density, temperature, u, v, w, pressure;
    // Scratch.
    std::vector<float> hat[5], next[5], omega[4], rhs, pressureTmp;
    std::vector<float> planeA, planeB;  // per z-plane reduction partials (fixed order)
    std::vector<double> planeSum, planeSumAfter;  // per z-plane density sums (mass renormalisation)
    static constexpr std::size_t kScratchRows = 3;  // advection: a row's trace (x, y, z)
    std::vector<float> rowScratch;                 // kScratchRows x rows per z-plane, so step() never allocates
    // Red-black Gauss-Seidel works on the two colours stored apart (row r = j + ny k holds its
    // cells of one colour at (i >> 1) in rbWidth() slots), so each sweep is contiguous.
    std::vector<float> rbPressure[2], rbRhs[2], rbDiagInv[2];
    int rbWidth() const { return (grid.nx + 1) / 2; }

    Vec3 centre;           // detonation point
    std::size_t startCell = 0;  // the free cell nearest the centre: the flood fill's and emitter's seed
    Vec3 emitterCentre;
    bool regionOpen = false;  // the centre's fluid region reaches an open border cell
    std::size_t fluidCells = 0, emitterCells = 0;
    double age = 0;
    SmokeStats stats;

    float* field(int n) {  // 0 density, 1 temperature, 2 u, 3 v, 4 w
        std::vector<float>* f[5] = {&density, &temperature, &u, &v, &w};
        return f[n]->data();
    }
};

// Builds classes, masks, diagInv and the emitter source from voxelSolid (creation time).
void initialiseState(SmokeState& s, const SmokeSettings& settings);
// Recomputes cellClass, faceMask and diagInv for z-planes [k0, k1] from staticClass + dynamicCells.
void rebuildDerived(SmokeState& s, int k0, int k1);

// One solver substep of dt seconds (emitter, advection, forces, projection, dissipation).
// The fast path uses `pool`; the reference path is single-threaded with plain loops.
void substepFast(SmokeState& s, const SmokeSettings& settings, ThreadPool& pool, float dt);
bool avx2PathAvailable();  // the CPU runs the AVX2 build of substepFast (VectorIsa::Best uses it)
void substepReference(SmokeState& s, const SmokeSettings& settings, float dt);

// Shared small pieces used by both paths.
void applyEmitter(SmokeState& s, const SmokeSettings& settings, float dt);
void patchDynamicFaces(SmokeState& s);
void setBorderFaces(SmokeState& s);
float densityDecay(const SmokeState& s, const SmokeSettings& settings, float dt);
// Density (as a sum over cells) leaving through open border faces in dt, upwind.
double borderOutflow(const SmokeState& s, float dt);
// The factor that restores the advected density's total to (before - outflow) * decay.
float massScale(const SmokeSettings& settings, double before, double outflow, double after, float decay);
// Sum of density over plane k's interior cells, in row order (what both paths reduce with).
double planeDensity(const std::vector<float>& density, const kernels::Dims& d, int k);

}  // namespace obscura::smoke
