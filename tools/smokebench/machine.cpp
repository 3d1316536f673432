#include "machine.h"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "smoke/thread_pool.h"

namespace smokebench {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// 12 independent chains of x = x * m + a: enough in flight to cover the latency of the two
// multiply and two add pipes; 2 flops per lane per chain step. A macro, not a template: a
// template instantiated for the AVX2 vectors would be compiled for the baseline target.
constexpr int kChains = 12;
#define SMOKEBENCH_CHAINS(NAME, V)                                               \
    double NAME(long steps, float seed) {                                        \
        V x[kChains];                                                            \
        const V m = V{} + 0.999999f, a = V{} + 1e-7f;                            \
        for (int c = 0; c < kChains; ++c) x[c] = V{} + (seed + 0.01f * c);       \
        for (long s = 0; s < steps; ++s)                                         \
            for (int c = 0; c < kChains; ++c) x[c] = x[c] * m + a;               \
        float sink = 0;                                                          \
        for (int c = 0; c < kChains; ++c) sink += x[c][0];                       \
        volatile float keep = sink;                                              \
        (void)keep;                                                              \
        return 2.0 * kChains * (sizeof(V) / sizeof(float)) * static_cast<double>(steps); \
    }

typedef float V4 __attribute__((vector_size(16)));
SMOKEBENCH_CHAINS(chainsSse, V4)
#if defined(__x86_64__) && defined(__GNUC__)
#pragma GCC push_options
#pragma GCC target("avx2")
typedef float V8 __attribute__((vector_size(32)));
SMOKEBENCH_CHAINS(chainsAvx2, V8)
#pragma GCC pop_options
#else
double chainsAvx2(long steps, float seed) { return chainsSse(steps, seed); }
#endif

std::vector<pid_t> competitors;

}  // namespace

double triadGBs(obscura::smoke::ThreadPool& pool, std::size_t n, int reps) {
    std::vector<double> a(n), b(n), c(n);
    const int chunks = 64;
    pool.parallelFor(chunks, [&](int c0, int c1) {  // first touch on the threads that use it
        for (std::size_t i = n * c0 / chunks; i < n * c1 / chunks; ++i) {
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
            for (std::size_t i = n * c0 / chunks; i < n * c1 / chunks; ++i) pa[i] = pb[i] + s * pc[i];
        });
        best = std::min(best, seconds(t0, Clock::now()));
    }
    volatile double sink = a[n / 2];
    (void)sink;
    return 3.0 * 8.0 * static_cast<double>(n) / best / 1e9;
}

double peakGflops(obscura::smoke::ThreadPool& pool, bool avx2) {
    const int threads = pool.threads();
    const long steps = 20'000'000 / kChains;
    double best = 0;
    for (int r = 0; r < 3; ++r) {
        std::vector<double> flops(static_cast<std::size_t>(threads), 0.0);
        const auto t0 = Clock::now();
        pool.parallelFor(threads, [&](int b, int e) {
            for (int t = b; t < e; ++t)
                flops[static_cast<std::size_t>(t)] = avx2 ? chainsAvx2(steps, 1.0f + t) : chainsSse(steps, 1.0f + t);
        });
        const double dt = seconds(t0, Clock::now());
        double total = 0;
        for (double f : flops) total += f;
        best = std::max(best, total / dt / 1e9);
    }
    return best;
}

void startCompetitors(int n) {
    for (int i = 0; i < n; ++i) {
        const pid_t pid = fork();
        if (pid == 0) {
            prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the benchmark
            volatile unsigned long spin = 0;
            for (;;) spin = spin + 1;
        }
        if (pid > 0) competitors.push_back(pid);
    }
}

void stopCompetitors() {
    for (pid_t pid : competitors) kill(pid, SIGKILL);
    for (pid_t pid : competitors) waitpid(pid, nullptr, 0);
    competitors.clear();
}

}  // namespace smokebench
