// Knobs of the smoke solver. Every tuned constant carries the reason for its value.
#pragma once

#include "core/vec3.h"

namespace obscura::smoke {

enum class PressureSolver {
    Jacobi,               // two buffers, p' = (sum of neighbours + rhs) / n
    RedBlackGaussSeidel,  // in place, red cells then black: about twice Jacobi's convergence per
                          // iteration at the same memory traffic (measured: see README.md)
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

    // Pressure projection. 20 red-black Gauss-Seidel iterations, warm-started from the previous
    // step's pressure: measured to leave a max residual divergence of ~3 % of the pre-projection
    // one after the first second (README.md); 40 only halves it, at twice the cost.
    int pressureIterations = 20;
    PressureSolver pressureSolver = PressureSolver::RedBlackGaussSeidel;

    int threads = 0;  // 0: hardware concurrency. Results are bitwise identical for any count.
    VectorIsa vectorIsa = VectorIsa::Best;  // results are bitwise identical for either

    // Lifetime (CS-style smoke grenade): emit for 3 s, hold, fade over the last 4 s, gone at 18 s.
    double lifetime = 18.0;
    double emitTime = 3.0;
    double fadeTime = 4.0;  // the density dissipation ramps up over this long before `lifetime`

    // Emitter: a sphere at the detonation point (lifted by emitterLift so a grenade lying on the
    // floor does not sit half in it).
    double emitterRadius = 0.5;      // metres: the canister's plume at 2 cells wide
    double emitterLift = 0.3;        // metres above the detonation point
    double emitDensity = 30.0;       // density units per second inside the sphere; the outflow
                                     // below dilutes it to ~2 at the canister, ~0.8 in the cloud
    double emitTemperature = 3.0;    // kelvin above ambient: a gentle rise, the cloud still hugs
                                     // the floor as a dome instead of shooting to the ceiling
    double emitExpansion = 20.0;     // 1/s volume source in the sphere (~10 m^3/s of gas): the
                                     // canister pushes the cloud out to a ~3.5 m radius dome
                                     // (measured in a 40 x 4 x 40 m hall: 43 m^3 above density 0.1
                                     // after 9 s, like a CS smoke); faces near it run at ~4 m/s
    Vec3 emitVelocity{0, 0, 0};      // m/s added inside the sphere each step (e.g. a jet direction)

    // Forces. buoyancy (Fedkiw et al. 2001): a = (buoyancy * T - densityWeight * density) up.
    double buoyancy = 0.12;          // m/s^2 per kelvin: with emitTemperature the plume lifts at
                                     // ~0.36 m/s^2, enough to roll, not to pool under the ceiling
    double densityWeight = 0.08;     // m/s^2 per density unit: cooled smoke settles slowly
    double vorticity = 0.35;         // confinement epsilon (dimensionless, x cell size): keeps
                                     // billows alive at 25 cm cells without visible noise
    double maxSpeed = 20.0;          // m/s velocity clamp: a guard against blow-ups, never reached
                                     // in normal play (the emitter pushes ~4 m/s)

    // Dissipation, per second (exponential).
    double densityDissipation = 0.02;     // smoke thins slowly while the grenade lasts
    double temperatureDissipation = 0.6;  // the plume cools within a couple of seconds, then settles
    double velocityDissipation = 0.15;    // stops the cloud drifting forever in a closed room
    double fadeDissipation = 2.5;         // extra density decay at the end of the fade: ramped over
                                          // fadeTime it leaves ~1 % (e^-5) at `lifetime`

    // MacCormack advection is not conservative (Selle et al. trade that for sharpness): near walls
    // and in converging flow it gains or loses several % per second. On: after each advection the
    // density is scaled so its total equals the total before, minus what left through open
    // border faces, times the dissipation (a global factor, invisible; README.md has figures).
    bool conserveMass = true;

    // Advection safety: a step is split so no trace goes further than maxCfl cells; each trace
    // is in any case clamped to one cell per axis, which is what keeps smoke from crossing a
    // one-cell wall (see README.md).
    double maxCfl = 1.0;
    int maxSubsteps = 4;
    double maxStep = 0.1;  // seconds: longer dt values are clamped (a hitch should not explode it)

    // Grid border cells that are inside the level: open (smoke flows out and is gone) or solid.
    bool openBorder = true;

    // Self-shadowing: transmittance = exp(-shadowSigma * integral of density along the light ray).
    double shadowSigma = 4.0;  // per metre per density unit: density 1 over 25 cm passes e^-1
    double exportDensityScale = 1.0;  // density mapped to 1.0 (255) in the packed texture
};

}  // namespace obscura::smoke
