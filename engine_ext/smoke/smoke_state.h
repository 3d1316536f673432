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
#include "smoke/smoke_multigrid.h"
#include "smoke/smoke_settings.h"

namespace obscura::smoke {

class ThreadPool;

// What the last step did (the last substep's figures where it was split).
struct SmokeStats {
    int substeps = 0;
    int pressureIterations = 0;   // of the last substep (MultigridCG: CG iterations taken)
    int pressureIterationsTotal = 0;  // summed over the step's substeps
    double divergenceBefore = 0;  // max |div u - source| over fluid cells before the projection (1/s)
    double residual = 0;          // max |div u - source| left after it (1/s)
    double worstRelativeResidual = 0;  // max over the step's substeps of residual / divergenceBefore
                                       // (substeps whose residual is under the absolute floor: 0)
    double maxSpeed = 0;          // m/s at the step's start: the largest sum of a cell's outgoing face speeds
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
    // Scratch. Advection: velHat = MacCormack's forward step of u, v, w; next = the new fields;
    // flux[f][a] = scalar f's (0 density, 1 temperature) flux through each cell's lower face on
    // axis a; outflow = each cell's outflow cap for the substep (kernels::outflowCap).
    std::vector<float> velHat[3], next[5], flux[2][3], outflow;
    std::vector<float> omega[4], rhs, pressureTmp;
    std::vector<float> planeA, planeB;  // per z-plane reduction partials (fixed order)
    static constexpr std::size_t kScratchRows = 3;  // advection: a row's trace (x, y, z)
    std::vector<float> rowScratch;                 // kScratchRows x rows per z-plane, so step() never allocates
    // Red-black Gauss-Seidel works on the two colours stored apart (row r = j + ny k holds its
    // cells of one colour at (i >> 1) in rbWidth() slots), so each sweep is contiguous.
    std::vector<float> rbPressure[2], rbRhs[2], rbDiagInv[2];
    int rbWidth() const { return (grid.nx + 1) / 2; }
    Multigrid mg;  // MultigridCG's levels and vectors

    Vec3 centre;           // detonation point
    std::size_t startCell = 0;  // the free cell nearest the centre: the flood fill's and emitter's seed
    Vec3 emitterCentre;
    bool regionOpen = false;  // the centre's fluid region reaches an open border cell
    bool staticRegionOpen = false;  // regionOpen as the walls alone make it (sealMovingObstacles changes regionOpen)
    bool sourceResealed = false;    // `source` is sealMovingObstacles' rather than initialiseState's
    std::size_t fluidCells = 0, emitterCells = 0;
    std::vector<std::size_t> emitterList;  // the emitter's cells (see initialiseState), nearest first
    float emitterRate = 0;  // volume source per emitter cell (1/s): emitGasRate / (cells x h^3)
    double age = 0;
    float projectedSource = 0;  // the emitter's factor the last projection used (1 emitting, 0 not)
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
// Moving obstacles (`cells`, about to become s.dynamicCells) can cut the centre's region apart (a
// door closed between two rooms): the fluid cells no longer 6-connected to the centre are
// appended to `cells` (solid for the step, at rest), and when that leaves the region closed
// although the walls alone left it open (or the other way), or seals anything, the sources are
// made again for the region as it is now (a closed region absorbs the emission uniformly). Without
// this the pressure problem has a second closed region or an incompatible source and CG diverges.
// Costs one flood fill of the grid.
void sealMovingObstacles(SmokeState& s, const SmokeSettings& settings, std::vector<DynamicCell>& cells);

// One solver substep of dt seconds (emitter, advection, forces, projection, dissipation).
// The fast path uses `pool`; the reference path is single-threaded with plain loops.
void substepFast(SmokeState& s, const SmokeSettings& settings, ThreadPool& pool, float dt);
bool avx2PathAvailable();  // the CPU runs the AVX2 build of substepFast (VectorIsa::Best uses it)
void substepReference(SmokeState& s, const SmokeSettings& settings, float dt);

// Shared small pieces used by both paths.
void applyEmitter(SmokeState& s, const SmokeSettings& settings, float dt);
void patchDynamicFaces(SmokeState& s);
void setBorderFaces(SmokeState& s);
void projectBorderFaces(SmokeState& s);
float densityDecay(const SmokeState& s, const SmokeSettings& settings, float dt);
// A substep's projection figures into the step's stats (max divergence before / after, 1/s;
// what is left under `floor` 1/s counts as divergence-free: SmokeSettings::pressureAbsoluteTolerance).
void recordProjection(SmokeStats& stats, float before, float after, int iterations, double floor);
// Outflow rate (1/s, kernels::outflowRate) of fluid cell c, 0 for any other cell.
float cellOutflowRate(const SmokeState& s, std::size_t c);
// Its outflow cap for a step of dt (kernels::outflowCap).
float cellOutflowCap(const SmokeState& s, std::size_t c, float dt);
// Max over cells of cellOutflowRate (what the substep count is chosen from), fast and plain.
float maxOutflowRate(SmokeState& s, ThreadPool& pool);
float maxOutflowRateReference(const SmokeState& s);
// The MultigridCG solve of s.rhs into s.pressure (warm start), both paths.
PressureSolveStats solvePressureFast(SmokeState& s, const SmokeSettings& settings, ThreadPool& pool);
PressureSolveStats solvePressureReference(SmokeState& s, const SmokeSettings& settings);

}  // namespace obscura::smoke
