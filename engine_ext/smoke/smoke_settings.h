// Knobs of the smoke solver. Every tuned constant carries the reason for its value.
#pragma once

#include "core/vec3.h"

namespace obscura::smoke {

enum class PressureSolver {
    MultigridCG,          // conjugate gradients preconditioned by a multigrid V-cycle (McAdams et al.
                          // 2010), iterated to pressureTolerance: the default (README.md, "Pressure")
    Jacobi,               // fixed pressureIterations sweeps, two buffers (for comparison)
    RedBlackGaussSeidel,  // fixed pressureIterations sweeps, in place, red cells then black: about
                          // twice Jacobi's convergence per sweep (for comparison)
};

// Which build of the optimised solver runs (smoke_solver_fast.cpp). Both give bitwise-equal
// fields; Baseline exists to test that and to measure the difference.
enum class VectorIsa {
    Best,      // AVX2 (8 floats a vector) where the CPU has it, else the baseline
    Baseline,  // x86-64 baseline: SSE2, 4 floats a vector
};

struct SmokeSettings {
    // Grid. 64^3 x 0.25 m = a 16 m box centred on the detonation point: room-sized smoke with
    // 25 cm detail (the renderer adds sub-grid noise). Clamped to [16, 128] with a warning.
    int resolution = 64;
    double cellSize = 0.25;

    // Pressure projection (MultigridCG): iterate until the largest divergence left is at most
    // pressureTolerance times the largest before the projection. 2.5e-4 leaves a factor 4 under the
    // 1e-3 the solver promises (the recursive residual CG stops on drifts a little from the true
    // one); measured in play it takes 1-8 iterations a substep (README.md). The absolute floor: below
    // 1e-5 1/s (a cell's volume changing by 0.001 % a second) a flow counts as divergence-free
    // even if the relative figure is not reached (a nearly still cloud).
    PressureSolver pressureSolver = PressureSolver::MultigridCG;
    double pressureTolerance = 2.5e-4;
    double pressureAbsoluteTolerance = 1e-5;  // 1/s
    int pressureMaxIterations = 40;  // a guard (absurd inputs); play never comes near it
    int pressureIterations = 20;     // Jacobi / red-black Gauss-Seidel: fixed sweeps per substep

    int threads = 0;  // 0: hardware concurrency. Results are bitwise identical for any count.
    VectorIsa vectorIsa = VectorIsa::Best;  // results are bitwise identical for either

    // Lifetime, like a Counter-Strike 2 smoke: the canister releases its gas in the first
    // emitTime seconds (the cloud blooms to its size in about a second), the cloud holds, and
    // thins out over the last fadeTime seconds; gone at 18 s.
    double lifetime = 18.0;
    double emitTime = 1.2;
    double fadeTime = 3.5;  // the density decay ramps from 0 to fadeDissipation over this long

    // Emitter. The gas enters the cells nearest the canister that the canister's own cell reaches
    // through open faces (never through a wall), as many as a free sphere of emitterRadius holds
    // (fewer only in a space smaller than that), at emitGasRate m^3/s in total wherever the
    // grenade lies: the gas is a volume source (divergence) in the pressure equation, and carries
    // emitSmokeDensity and emitTemperature in with it, so the cloud's density is the gas's,
    // diluted only by mixing.
    double emitterRadius = 1.0;    // metres (268 cells of 0.25 m): the gas leaves it slowly enough
                                   // for 2 substeps a 20 Hz step during the bloom (a 0.75 m one
                                   // needed 4, for the same bloom: README.md, "Tuning")
    double emitterLift = 0.3;      // metres above the detonation point (the canister's plume)
    double emitGasRate = 50.0;     // m^3/s for emitTime: 60 m^3 of smoke, a ~3 m radius dome on
                                   // open floor within a second or so (CS2's smoke is ~3.5 m wide)
    double emitSmokeDensity = 1.0; // density units of the released gas: 1 = extinction shadowSigma
                                   // per metre (the renderer's own scale; README.md, "Density")
    double emitTemperature = 1.0;  // kelvin above ambient of all the gas (the old 3 K was held only
                                   // in the emitter's cells): the dome rolls a little, then settles
                                   // as it cools (centre of mass 1.1-1.4 m; 3 K: up to 1.5 m)
    Vec3 emitVelocity{0, 0, 0};    // m/s set on the emitter cells' faces (e.g. a jet direction)

    // Forces. buoyancy (Fedkiw et al. 2001): a = (buoyancy * T - densityWeight * density) up.
    double buoyancy = 0.12;          // m/s^2 per kelvin: with emitTemperature the plume lifts at
                                     // ~0.36 m/s^2, enough to roll, not to pool under the ceiling
    double densityWeight = 0.08;     // m/s^2 per density unit: cooled smoke settles slowly
    double vorticity = 0.35;         // confinement epsilon (dimensionless, x cell size): keeps
                                     // billows alive at 25 cm cells without visible noise
    double maxSpeed = 20.0;          // m/s velocity clamp: a guard against blow-ups, never reached
                                     // in normal play

    // Modelled decays, per second (exponential). Smoke mass is otherwise conserved exactly by the
    // transport: there is no dissipation for numerical reasons and no renormalisation.
    double densityDissipation = 0.0;      // none while the cloud holds (CS2 smoke does not thin)
    double temperatureDissipation = 0.6;  // the plume cools within a couple of seconds, then settles
    double velocityDissipation = 1.0;     // drag of the unresolved turbulence: without it the bloom's
                                          // vortex ring carries the cloud off the floor (at 0.15 /s
                                          // its centre of mass rose from 1.4 to 4.2 m in 8 s; at 1 /s
                                          // it stays at 1.4-1.7 m all its life, like CS2's dome)
    double fadeDissipation = 3.0;         // the end of the grenade: ramped over fadeTime it leaves
                                          // e^-5.25 ~ 0.5 % at `lifetime`

    // Time stepping: a step is split so that no cell's outflow courant number (the sum of its
    // outgoing face speeds x dt / h) exceeds maxCfl: the flux transport then moves smoke at its
    // true speed and the outflow cap (positivity) rarely engages; each velocity trace is in any
    // case clamped to one cell per axis, which keeps smoke from crossing a one-cell wall.
    double maxCfl = 1.0;
    int maxSubsteps = 4;
    double maxStep = 0.1;  // seconds: longer dt values are clamped (a hitch should not explode it)

    // Grid border cells that are inside the level: open (smoke flows out and is gone) or solid.
    bool openBorder = true;

    // Self-shadowing: transmittance = exp(-shadowSigma * integral of density along the light ray).
    double shadowSigma = 4.0;  // per metre per density unit: density 1 over 25 cm passes e^-1
    double exportDensityScale = 2.0;  // density mapped to 1.0 (255) in exportRG8: in open space the
                                      // cloud never exceeds emitSmokeDensity (1); a sealed room
                                      // compresses the gas and reaches ~2 (measured 1.99 in the
                                      // tests' sealed 69 m^3 room), so nothing saturates
};

}  // namespace obscura::smoke
