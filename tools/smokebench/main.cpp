// obscura_smokebench: the smoke solver's step at 32^3, 64^3 (and 96^3) on the honest roofline of
// this machine, measured in the same run: the least memory traffic a step needs (every field
// read and written once) against DRAM and L3 bandwidth, and the arithmetic it does against the
// machine's peak. Also the relaxation solvers the MGPCG replaced, the scalar reference, the
// renderer's per-frame work and the thread pool on 1 and N threads, optionally with other
// CPU-heavy processes competing for the cores.
//
// Usage: obscura_smokebench [--threads N] [--quick] [--baseline] [--compete N] [--only64]
//   --baseline: the SSE2 build of the optimised solver even where the CPU has AVX2. The roofline's
//     peak is the machine's either way: on its widest vectors (AVX-512 where it has it), the bound
//     a step cannot beat on this machine whichever build runs
//   --compete N: N spinning child processes run during the timings (an oversubscribed machine)
//   --only64: the 64^3 play row alone (for before/after runs)
// Prints a table and one machine-readable line starting with "smokebench ".
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "machine.h"
#include "map/level.h"
#include "smoke/smoke_volume.h"
#include "smoke/thread_pool.h"

using namespace obscura;
using namespace obscura::smoke;

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// ---- What one substep must move, and the arithmetic it does, per cell ----
// Bytes: the six fields (density, temperature, u, v, w, pressure) read and written once
// (6 x 8 B) and the per-cell inputs read once (cell class 1 B, three face masks 3 B, the
// emitter's source 4 B): 56 B. Everything else the solver touches (hats, fluxes, multigrid
// levels, CG vectors) is its own choice, not a need.
constexpr double kMinBytesPerCell = 6 * 8 + 1 + 3 + 4;
// Arithmetic (adds, subtracts, multiplies, divides, square roots; not compares, selects, min,
// max, abs), counted from smoke_kernels.h per cell:
//   outflow rates and caps, twice (the step's substep count, the substep's caps)     2 x 8 = 16
//   face fluxes: 3 faces x (3 shared + 2 scalars x 10)                                   69
//   scalar updates: 2 x (6 + decay)                                                      14
//   velocity MacCormack: 3 x (2 traces x 11 + forward blend 21 + reverse 21 + 4)        204
//   forces: curl 36, |curl| 6, confinement 26, face forces 20                            88
//   divergence and right-hand side                                                       10
//   gradient and residual                                                                19
//   MGPCG: residual 8 + V-cycle 78 to start; per iteration A d and <d, q> 9, updates 4,
//     V-cycle 78 (level 0: 5 Jacobi sweeps x 10, residual 8, transfer 2, dot 2, start 2;
//     coarser levels ~1/7 of a cell's 98), new direction 2: 93; the last skips the last 80
//   relaxation solvers instead: 7 per sweep (neighbour sum 5, update 2)
constexpr double kFlopsFixed = 16 + 69 + 14 + 204 + 88 + 10 + 19;
constexpr double kFlopsMgStart = 8 + 78 - 80, kFlopsMgIteration = 93, kFlopsRelaxSweep = 7;

struct Machine {
    double dramGBs = 0, l3GBs = 0, peakGflops = 0;
};

// A big closed hall (40 x 14 x 40 m) with two pillars: every grid up to 96^3 x 0.25 m is fluid
// except the floor and the pillars, so no step is cheap for lack of smoke room.
map::LevelBrush box(const Vec3& mn, const Vec3& mx) {
    map::LevelBrush b;
    for (int i = 0; i < 8; ++i) b.hullPoints.push_back({i & 1 ? mx.x : mn.x, i & 2 ? mx.y : mn.y, i & 4 ? mx.z : mn.z});
    b.bounds.extend(mn);
    b.bounds.extend(mx);
    return b;
}
map::Level hall() {
    map::Level l;
    l.entities.resize(1);
    l.brushes.push_back(box({-20, -1, -20}, {20, 0, 20}));
    l.brushes.push_back(box({-20, 14, -20}, {20, 15, 20}));
    l.brushes.push_back(box({-21, -1, -20}, {-20, 15, 20}));
    l.brushes.push_back(box({20, -1, -20}, {21, 15, 20}));
    l.brushes.push_back(box({-20, -1, -21}, {20, 15, -20}));
    l.brushes.push_back(box({-20, -1, 20}, {20, 15, 21}));
    l.brushes.push_back(box({2, 0, 1}, {3, 14, 2}));
    l.brushes.push_back(box({-4, 0, -3}, {-3, 14, -2}));
    for (const auto& b : l.brushes) {
        l.bounds.extend(b.bounds.min);
        l.bounds.extend(b.bounds.max);
    }
    return l;
}

struct Timing {
    double msPerStep = 0, substeps = 0, iterations = 0;  // substeps per step, solver iterations per substep
    double divergenceBefore = 0, residual = 0, worstRelative = 0;
    double advect = 0, forces = 0, pressure = 0, project = 0;  // ms per step per phase (optimised path)
};

// Warm up `warmup` steps of 1/30 s, then time `blocks` blocks of `perBlock` steps and keep the
// fastest block's figures: this machine is shared, and another process's burst should not count
// as the solver's time. Divergence figures over all timed steps.
Timing timeSteps(SmokeVolume& vol, int warmup, int perBlock, int blocks, bool reference) {
    for (int i = 0; i < warmup; ++i) vol.step(1.0 / 30);
    Timing best;
    best.msPerStep = 1e300;
    double before = 0, residual = 0, worst = 0;
    for (int b = 0; b < blocks; ++b) {
        Timing t;
        double subs = 0, its = 0;
        const auto t0 = Clock::now();
        for (int i = 0; i < perBlock; ++i) {
            if (reference) vol.stepReference(1.0 / 30);
            else vol.step(1.0 / 30);
            const SmokeStats& s = vol.stats();
            before += s.divergenceBefore / (perBlock * blocks);
            residual += s.residual / (perBlock * blocks);
            worst = std::max(worst, s.worstRelativeResidual);
            subs += s.substeps;
            its += s.pressureIterationsTotal;
            t.advect += s.msAdvect / perBlock;
            t.forces += s.msForces / perBlock;
            t.pressure += s.msPressure / perBlock;
            t.project += s.msProject / perBlock;
        }
        t.msPerStep = 1e3 * seconds(t0, Clock::now()) / perBlock;
        t.substeps = subs / perBlock;
        t.iterations = its / subs;
        if (t.msPerStep < best.msPerStep) best = t;
    }
    best.divergenceBefore = before;
    best.residual = residual;
    best.worstRelative = worst;
    return best;
}

struct Roofline {
    double mb, mflop, dramMs, l3Ms, computeMs;
    double roofMs() const { return std::max(dramMs, computeMs); }
};
Roofline roofline(const Machine& m, std::size_t cells, const Timing& t, PressureSolver solver, int sweeps) {
    const double perSubstep = kFlopsFixed + (solver == PressureSolver::MultigridCG ? kFlopsMgStart + kFlopsMgIteration * t.iterations
                                                                                  : kFlopsRelaxSweep * sweeps);
    Roofline r{};
    r.mb = static_cast<double>(cells) * kMinBytesPerCell * t.substeps / 1e6;
    r.mflop = static_cast<double>(cells) * perSubstep * t.substeps / 1e6;
    r.dramMs = r.mb / m.dramGBs;
    r.l3Ms = r.mb / m.l3GBs;
    r.computeMs = r.mflop / m.peakGflops;
    return r;
}

const char* solverName(PressureSolver s) {
    return s == PressureSolver::MultigridCG ? "MGPCG" : s == PressureSolver::Jacobi ? "Jacobi-20" : "RBGS-20";
}

}  // namespace

int main(int argc, char** argv) {
    int threads = 0, compete = 0;
    bool quick = false, baseline = false, only64 = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) threads = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--compete") && i + 1 < argc) compete = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--quick")) quick = true;
        else if (!std::strcmp(argv[i], "--baseline")) baseline = true;
        else if (!std::strcmp(argv[i], "--only64")) only64 = true;
        else {
            std::fprintf(stderr, "usage: %s [--threads N] [--quick] [--baseline] [--compete N] [--only64]\n", argv[0]);
            return 2;
        }
    }
    const map::Level level = hall();
    const Vec3 centre{0, 0.05, 0};
    SmokeSettings base;
    base.threads = threads;
    base.vectorIsa = baseline ? VectorIsa::Baseline : VectorIsa::Best;
    const int solverLanes = !baseline && avx2PathAvailable() ? 8 : 4;  // the build the solver runs
    const int machineLanes = smokebench::widestLanes();                 // the machine's widest vectors
    const char* isaName = solverLanes == 8 ? "AVX2" : "baseline (SSE2)";
    auto pool = std::make_shared<ThreadPool>(threads);
    const int nThreads = pool->threads();

    Machine m;
    // DRAM: 3 x 32 M doubles = 768 MB, 24x the 32 MB L3 of the machine this was written on.
    // L3: 3 x 512 K doubles = 12 MB, over the 1 MB L2 of each core, well inside the L3.
    const std::size_t dramN = quick || only64 ? (std::size_t{8} << 20) : (std::size_t{32} << 20);
    m.dramGBs = smokebench::triadGBs(*pool, dramN, quick || only64 ? 3 : 6);
    m.l3GBs = smokebench::triadGBs(*pool, std::size_t{512} << 10, 60);
    m.peakGflops = smokebench::peakGflops(*pool, machineLanes);
    const double solverPeak = solverLanes == machineLanes ? m.peakGflops : smokebench::peakGflops(*pool, solverLanes);
    std::printf("obscura_smokebench: %d threads (hardware: %u), %s build of the solver%s\n", nThreads,
                std::thread::hardware_concurrency(), isaName,
                compete ? (", " + std::to_string(compete) + " competing CPU-bound processes").c_str() : "");
    std::printf("machine, measured now on %d threads: DRAM %.1f GB/s (STREAM triad, 3 x %zu doubles), L3 %.1f GB/s "
                "(triad, 12 MB), peak %.1f GFLOP/s (%d-float multiply + add, no FMA: the machine's widest; %d-float, "
                "the solver build's: %.1f)\n",
                nThreads, m.dramGBs, dramN, m.l3GBs, m.peakGflops, machineLanes, solverLanes, solverPeak);
    std::printf("a step's least traffic: %.0f B/cell a substep (6 fields read and written, class + masks + source read)\n\n",
                kMinBytesPerCell);
    std::printf("%-6s %-10s %5s %5s %9s %9s %9s %8s %8s %8s %7s %7s %7s %7s %6s\n", "grid", "solver", "subs", "its",
                "div_in", "rel_left", "ms/step", "MB_min", "MFLOP", "GFLOP/s", "dram_ms", "l3_ms", "fp_ms", "x_roof",
                "x_l3");
    if (compete) smokebench::startCompetitors(compete);

    std::string machine = "smokebench threads=" + std::to_string(nThreads) + " isa=" +
                          (solverLanes == 8 ? "avx2" : "baseline") +
                          " compete=" + std::to_string(compete) + " dram_gbs=" + std::to_string(m.dramGBs) +
                          " l3_gbs=" + std::to_string(m.l3GBs) + " peak_gflops=" + std::to_string(m.peakGflops) +
                          " solver_peak_gflops=" + std::to_string(solverPeak);
    auto row = [&](const char* label, int n, PressureSolver solver, bool reference, int warmup, int perBlock, int blocks,
                   std::shared_ptr<ThreadPool> rowPool) {
        SmokeSettings st = base;
        st.resolution = n;
        st.pressureSolver = solver;
        SmokeVolume vol = SmokeVolume::create(level, {}, centre, st, rowPool);
        const Timing t = timeSteps(vol, warmup, perBlock, blocks, reference);
        const Roofline r = roofline(m, vol.grid().cells(), t, solver, st.pressureIterations);
        std::printf("%3d^3  %-10s %5.2f %5.1f %9.3f %9.2e %9.2f %8.1f %8.0f %8.1f %7.2f %7.2f %7.2f %7.1f %6.1f  %s\n", n,
                    reference ? "reference" : solverName(solver), t.substeps, t.iterations, t.divergenceBefore,
                    t.worstRelative, t.msPerStep, r.mb, r.mflop, r.mflop / t.msPerStep, r.dramMs, r.l3Ms, r.computeMs,
                    t.msPerStep / r.roofMs(), t.msPerStep / std::max(r.l3Ms, r.computeMs), label);
        if (!reference)
            std::printf("       phases: advect %.2f ms, forces %.2f ms, pressure %.2f ms, projection %.2f ms\n", t.advect, t.forces,
                        t.pressure, t.project);
        std::fflush(stdout);
        const std::string key = std::string(label) + std::to_string(n);
        machine += " " + key + "_ms=" + std::to_string(t.msPerStep) + " " + key + "_roof_ms=" + std::to_string(r.roofMs()) +
                   " " + key + "_its=" + std::to_string(t.iterations) + " " + key + "_rel=" + std::to_string(t.worstRelative);
        return std::make_pair(t, std::move(vol));
    };
    // Play: 1.5 s into a grenade (the bloom is over), 4 blocks of 5 steps of 1/30 s.
    const int warmup = 45, perBlock = quick ? 3 : 5;
    auto [play64, vol64] = row("play", 64, PressureSolver::MultigridCG, false, warmup, perBlock, 4, pool);
    if (!only64) {
        row("play", 32, PressureSolver::MultigridCG, false, warmup, perBlock, 4, pool);
        if (!quick) row("play", 96, PressureSolver::MultigridCG, false, warmup, perBlock, 4, pool);
        // The bloom (0.3-0.7 s: the gas still pouring out, up to 4 substeps).
        row("bloom", 64, PressureSolver::MultigridCG, false, 9, 3, 4, pool);
        row("relax", 64, PressureSolver::RedBlackGaussSeidel, false, warmup, perBlock, 4, pool);
        row("relax", 64, PressureSolver::Jacobi, false, warmup, perBlock, 4, pool);
        const auto ref = row("ref", 64, PressureSolver::MultigridCG, true, warmup, quick ? 2 : 4, 1, std::make_shared<ThreadPool>(1));
        std::printf("\nspeedup at 64^3 (%d threads) over the scalar single-threaded reference: %.2fx\n", nThreads,
                    ref.first.msPerStep / play64.msPerStep);
        machine += " speedup64=" + std::to_string(ref.first.msPerStep / play64.msPerStep);

        // What the renderer adds per solver step: the transmittance toward the sun, the sky
        // visibility and the export it uploads (RGB32F; the RG8 export it replaced for comparison).
        std::vector<std::uint8_t> rg8;
        std::vector<float> rgb;
        const int reps = 5;
        double partMs[4] = {};
        for (int r = 0; r < reps; ++r) {
            auto a = Clock::now();
            vol64.computeTransmittance({0.3, 1.0, 0.2});
            auto b = Clock::now();
            vol64.computeSkyVisibility();
            auto c = Clock::now();
            vol64.exportRGBFloat(rgb);
            auto d = Clock::now();
            vol64.exportRG8(rg8);
            auto e = Clock::now();
            partMs[0] += 1e3 * seconds(a, b) / reps;
            partMs[1] += 1e3 * seconds(b, c) / reps;
            partMs[2] += 1e3 * seconds(c, d) / reps;
            partMs[3] += 1e3 * seconds(d, e) / reps;
        }
        const double shadowMs = partMs[0] + partMs[1] + partMs[2];
        std::printf("64^3 per step for the renderer: transmittance (light 0.3, 1, 0.2) %.2f ms + sky visibility %.2f ms + "
                    "RGB32F export %.2f ms = %.2f ms (the RG8 export: %.2f ms)\n",
                    partMs[0], partMs[1], partMs[2], shadowMs, partMs[3]);
        machine += " shadow64_ms=" + std::to_string(shadowMs);
        // The lamp maps of an upload with two shadowed lamps (SmokeRender: the sign lamps and the
        // brightest level lamps that reach the box): one 2.5 m above the floor at the cloud's
        // side, one outside the grid.
        std::vector<float> lampMaps;
        const auto l0 = Clock::now();
        for (int r = 0; r < reps; ++r) vol64.exportLampTransmittance({{3.0, 2.5, 1.0}, {12.0, 4.0, -3.0}}, lampMaps);
        const double lampMs = 1e3 * seconds(l0, Clock::now()) / reps;
        std::printf("64^3 lamp maps for the renderer, 2 lamps (RGBA32F): %.2f ms\n", lampMs);
        machine += " lamps64_ms=" + std::to_string(lampMs);

        // Thread scaling: the same 64^3 play row on one thread (the pool above has nThreads).
        if (nThreads > 1) {
            const auto one = row("one_thread", 64, PressureSolver::MultigridCG, false, warmup, perBlock, 4, std::make_shared<ThreadPool>(1));
            std::printf("64^3 on 1 thread %.2f ms, on %d threads %.2f ms: %.2fx\n", one.first.msPerStep, nThreads, play64.msPerStep,
                        one.first.msPerStep / play64.msPerStep);
            machine += " scaling64=" + std::to_string(one.first.msPerStep / play64.msPerStep);
        }
    }
    if (compete) smokebench::stopCompetitors();
    std::printf("\nsubs: substeps per step; its: MGPCG iterations per substep; rel_left: the largest divergence left after\n"
                "a projection over the largest before it; MB_min / MFLOP: the least traffic and the arithmetic per step;\n"
                "dram_ms / l3_ms / fp_ms: those at the measured DRAM and L3 bandwidth and the peak; x_roof: ms/step over\n"
                "max(dram_ms, fp_ms), the roofline's bound; x_l3: over max(l3_ms, fp_ms) (the state fits in the L3).\n"
                "ms/step: the fastest of 4 blocks (the reference: one block).\n");
    std::printf("%s\n", machine.c_str());
    return 0;
}
