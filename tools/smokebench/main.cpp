// obscura_smokebench: smoke solver step times at 32^3, 64^3 and 96^3 against a memory-bandwidth
// bound measured in the same run (STREAM triad), the pressure solvers compared, and the scalar
// single-threaded reference at 64^3.
//
// Usage: obscura_smokebench [--threads N] [--quick] [--baseline]
//   --baseline: the SSE2 build of the optimised solver even where the CPU has AVX2
// Prints a table and one machine-readable line starting with "smokebench ".
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "map/level.h"
#include "smoke/smoke_volume.h"
#include "smoke/thread_pool.h"

using namespace obscura;
using namespace obscura::smoke;

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// STREAM triad a[i] = b[i] + s * c[i] on the same thread count as the solver; best of `reps`.
// Bytes counted as STREAM does: 3 arrays x 8 bytes per element (no write-allocate).
double streamTriadGBs(ThreadPool& pool, std::size_t n, int reps) {
    std::vector<double> a(n), b(n), c(n);
    const int chunks = 64;
    pool.parallelFor(chunks, [&](int c0, int c1) {  // first touch on the threads that use it
        for (int ch = c0; ch < c1; ++ch)
            for (std::size_t i = n * ch / chunks; i < n * (ch + 1) / chunks; ++i) {
                a[i] = 0;
                b[i] = 1.0;
                c[i] = 2.0;
            }
    });
    double best = 1e30;
    const double s = 3.0;
    for (int r = 0; r < reps; ++r) {
        const auto t0 = Clock::now();
        pool.parallelFor(chunks, [&](int c0, int c1) {
            double* pa = a.data();
            const double *pb = b.data(), *pc = c.data();
            const std::size_t i0 = n * c0 / chunks, i1 = n * c1 / chunks;
            for (std::size_t i = i0; i < i1; ++i) pa[i] = pb[i] + s * pc[i];
        });
        best = std::min(best, seconds(t0, Clock::now()));
    }
    volatile double sink = a[n / 2];
    (void)sink;
    return 3.0 * 8.0 * static_cast<double>(n) / best / 1e9;
}

// The least a step must move between the cores and memory, per cell, counting each field array
// a pass reads or writes once (4-byte floats, 1-byte masks), as the passes are written:
//   advect forward: read u v w d T, write 5 hats                               40
//   advect correct: read 5 fields + 5 hats + class, write 5                     61
//   mass renormalisation: read + write density                                   8
//   curl: read u v w, write 3 components + |omega|                              28
//   confinement: read 4, write 3                                                28
//   forces + boundary: read 3 forces, T, d, u v w, 3 masks, write u v w         47
//   divergence: read u v w, class, source, write rhs                            21
//   gradient + residual: read p, u v w, 3 masks, rhs, diagInv, write u v w      39
//   substep speed scan: read u v w                                              12
//   RBGS only: split p, rhs, diagInv into colours (read 12, write 12), merge p (read 4,
//     write 4)                                                                   32
//   per pressure iteration: RBGS 2 sweeps x (read p 4 + rhs, diagInv of one
//     colour 4 + write one colour 2) = 20; Jacobi read p rhs diagInv + write 16
double bytesPerStep(std::size_t cells, int iterations, PressureSolver solver) {
    const double fixed = 40 + 61 + 8 + 28 + 28 + 47 + 21 + 39 + 12 + (solver == PressureSolver::Jacobi ? 0 : 32);
    const double perIteration = solver == PressureSolver::Jacobi ? 16 : 20;
    return static_cast<double>(cells) * (fixed + perIteration * iterations);
}

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
    double msPerStep = 0, residual = 0, divergenceBefore = 0;
    double advect = 0, forces = 0, pressure = 0, project = 0;  // ms per step per phase (optimised path)
    int iterations = 0;
};

// Warm up (the cloud forms, the warm start settles), then time `steps` steps of 1/30 s in
// `blocks` blocks and keep the fastest block's mean per step (and its phases): this machine is
// shared, and another process's burst should not count as the solver's time. Residuals are
// averaged over all steps.
Timing timeSteps(SmokeVolume& vol, int warmup, int steps, int blocks, bool reference) {
    for (int i = 0; i < warmup; ++i) vol.step(1.0 / 30);
    Timing best;
    best.msPerStep = 1e300;
    double residual = 0, divergence = 0;
    const int perBlock = std::max(1, steps / blocks);
    for (int b = 0; b < blocks; ++b) {
        Timing t;
        const auto t0 = Clock::now();
        for (int i = 0; i < perBlock; ++i) {
            if (reference) vol.stepReference(1.0 / 30);
            else vol.step(1.0 / 30);
            residual += vol.stats().residual / (perBlock * blocks);
            divergence += vol.stats().divergenceBefore / (perBlock * blocks);
            t.advect += vol.stats().msAdvect / perBlock;
            t.forces += vol.stats().msForces / perBlock;
            t.pressure += vol.stats().msPressure / perBlock;
            t.project += vol.stats().msProject / perBlock;
        }
        t.msPerStep = 1e3 * seconds(t0, Clock::now()) / perBlock;
        if (t.msPerStep < best.msPerStep) best = t;
    }
    best.residual = residual;
    best.divergenceBefore = divergence;
    best.iterations = vol.stats().pressureIterations * vol.stats().substeps;
    return best;
}

}  // namespace

int main(int argc, char** argv) {
    int threads = 0;
    bool quick = false, baseline = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) threads = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--quick")) quick = true;
        else if (!std::strcmp(argv[i], "--baseline")) baseline = true;
        else {
            std::fprintf(stderr, "usage: %s [--threads N] [--quick] [--baseline]\n", argv[0]);
            return 2;
        }
    }
    const map::Level level = hall();
    const Vec3 centre{0, 0.05, 0};
    SmokeSettings base;
    base.threads = threads;
    base.vectorIsa = baseline ? VectorIsa::Baseline : VectorIsa::Best;
    const bool avx2 = !baseline && avx2PathAvailable();
    auto pool = std::make_shared<ThreadPool>(threads);
    const int nThreads = pool->threads();

    // 3 x 32 M doubles = 768 MB: 24x the 32 MB L3 of the machine this was written on.
    const std::size_t streamN = quick ? (std::size_t{8} << 20) : (std::size_t{32} << 20);
    const double gbs = streamTriadGBs(*pool, streamN, quick ? 3 : 6);
    std::printf("obscura_smokebench: %d threads (hardware: %u), %s build of the solver\n", nThreads,
                std::thread::hardware_concurrency(), avx2 ? "AVX2" : "baseline (SSE2)");
    std::printf("STREAM triad over 3 x %zu doubles: %.2f GB/s\n\n", streamN, gbs);
    std::printf("%-6s %-10s %6s %10s %10s %9s %9s %9s %7s\n", "grid", "solver", "iters", "div_in", "residual", "ms/step",
                "MB/step", "bound_ms", "ratio");

    const int warmup = quick ? 10 : 45, steps = quick ? 5 : 20;
    std::string machine = "smokebench threads=" + std::to_string(nThreads) + " isa=" + (avx2 ? "avx2" : "baseline") +
                          " stream_gbs=" + std::to_string(gbs);
    double ms64 = 0;
    auto row = [&](int n, PressureSolver solver, bool reference) {
        SmokeSettings st = base;
        st.resolution = n;
        st.pressureSolver = solver;
        SmokeVolume vol = SmokeVolume::create(level, {}, centre, st, reference ? std::make_shared<ThreadPool>(1) : pool);
        const Timing t = timeSteps(vol, warmup, reference ? std::max(3, steps / 4) : steps, reference ? 1 : 4, reference);
        const double bytes = bytesPerStep(vol.grid().cells(), t.iterations, solver);
        const double boundMs = bytes / (gbs * 1e9) * 1e3;
        const char* name = reference ? "reference" : solver == PressureSolver::Jacobi ? "Jacobi" : "RBGS";
        std::printf("%3d^3  %-10s %6d %10.4f %10.5f %9.2f %9.1f %9.2f %7.2f\n", n, name, t.iterations, t.divergenceBefore,
                    t.residual, t.msPerStep, bytes / 1e6, boundMs, t.msPerStep / boundMs);
        if (!reference) {
            // The pressure iterations alone against their share of the bound (20 or 16 B/cell/iteration).
            const double pressureBytes = static_cast<double>(vol.grid().cells()) * t.iterations *
                                         (solver == PressureSolver::Jacobi ? 16 : 20);
            const double pressureBoundMs = pressureBytes / (gbs * 1e9) * 1e3;
            std::printf("       phases: advect %.2f ms, forces %.2f ms, pressure %.2f ms (bound %.2f, ratio %.2f), "
                        "projection %.2f ms\n",
                        t.advect, t.forces, t.pressure, pressureBoundMs, t.pressure / pressureBoundMs, t.project);
        }
        std::fflush(stdout);
        if (!reference && solver == PressureSolver::RedBlackGaussSeidel) {  // what the renderer adds per frame
            std::vector<std::uint8_t> rg8;
            const auto t0 = Clock::now();
            const int reps = 5;
            for (int r = 0; r < reps; ++r) {
                vol.computeTransmittance({0.3, 1.0, 0.2});
                vol.exportRG8(rg8);
            }
            const double ms = 1e3 * seconds(t0, Clock::now()) / reps;
            std::printf("       transmittance (light 0.3, 1, 0.2) + RG8 export: %.2f ms\n", ms);
            machine += " shadow" + std::to_string(n) + "_ms=" + std::to_string(ms);
        }
        const std::string key = std::string(reference ? "ref" : solver == PressureSolver::Jacobi ? "jacobi" : "rbgs") +
                                std::to_string(n);
        machine += " " + key + "_ms=" + std::to_string(t.msPerStep) + " " + key + "_bound_ms=" + std::to_string(boundMs) +
                   " " + key + "_residual=" + std::to_string(t.residual);
        return t.msPerStep;
    };
    row(32, PressureSolver::RedBlackGaussSeidel, false);
    ms64 = row(64, PressureSolver::RedBlackGaussSeidel, false);
    row(64, PressureSolver::Jacobi, false);
    if (!quick) row(96, PressureSolver::RedBlackGaussSeidel, false);
    const double ref = row(64, PressureSolver::RedBlackGaussSeidel, true);
    std::printf("\nspeedup at 64^3 (RBGS, %d threads) over the scalar single-threaded reference: %.2fx\n", nThreads,
                ref / ms64);
    std::printf("ratio = ms/step / bound_ms, bound = MB/step at the STREAM figure (see bytesPerStep for the count);\n"
                "ms/step: the fastest of 4 blocks of %d steps (the reference: one block)\n", std::max(1, steps / 4));
    machine += " speedup64=" + std::to_string(ref / ms64);
    std::printf("%s\n", machine.c_str());
    return 0;
}
