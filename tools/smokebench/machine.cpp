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

// Independent chains of x = x * m + a, 2 flops per lane per chain step. A step is a multiply
// then an add (~6 cycles of latency), so feeding the two multiply and two add pipes needs 12
// chains in flight: 12 where there are 16 vector registers (SSE2, AVX2: 16 chains would spill
// and measure the spills), 24 where there are 32 (AVX-512). A macro, not a template: a template
// instantiated for the wider vectors would be compiled for the baseline target.
#define SMOKEBENCH_CHAINS(NAME, V, CHAINS)                                       \
    double NAME(long steps, float seed) {                                        \
        constexpr int kChains = CHAINS;                                          \
        V x[kChains];                                                            \
        const V m = V{} + 0.999999f, a = V{} + 1e-7f;                            \
        for (int c = 0; c < kChains; ++c) x[c] = V{} + (seed + 0.01f * c);       \
        steps = steps * 12 / kChains; /* the same work for every chain count */  \
        for (long s = 0; s < steps; ++s) {                                       \
            _Pragma("GCC unroll 32") /* chains in registers, not an array */    \
            for (int c = 0; c < kChains; ++c) x[c] = x[c] * m + a;               \
        }                                                                        \
        float sink = 0;                                                          \
        for (int c = 0; c < kChains; ++c) sink += x[c][0];                       \
        volatile float keep = sink;                                              \
        (void)keep;                                                              \
        return 2.0 * kChains * (sizeof(V) / sizeof(float)) * static_cast<double>(steps); \
    }

typedef float V4 __attribute__((vector_size(16)));
SMOKEBENCH_CHAINS(chainsSse, V4, 12)
#if defined(__x86_64__) && defined(__GNUC__)
#pragma GCC push_options
#pragma GCC target("avx2")
typedef float V8 __attribute__((vector_size(32)));
SMOKEBENCH_CHAINS(chainsAvx2, V8, 12)
#pragma GCC pop_options
#pragma GCC push_options
#pragma GCC target("avx512f")
typedef float V16 __attribute__((vector_size(64)));
SMOKEBENCH_CHAINS(chainsAvx512, V16, 24)
#pragma GCC pop_options
#else
double chainsAvx2(long steps, float seed) { return chainsSse(steps, seed); }
double chainsAvx512(long steps, float seed) { return chainsSse(steps, seed); }
#endif

std::vector<pid_t> competitors;

}  // namespace

int widestLanes() {
#if defined(__x86_64__) && defined(__GNUC__)
    if (__builtin_cpu_supports("avx512f")) return 16;
    if (__builtin_cpu_supports("avx2")) return 8;
#endif
    return 4;
}

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

double peakGflops(obscura::smoke::ThreadPool& pool, int lanes) {
    const int threads = pool.threads();
    const long steps = 20'000'000 / 12;
    double best = 0;
    for (int r = 0; r < 3; ++r) {
        std::vector<double> flops(static_cast<std::size_t>(threads), 0.0);
        const auto t0 = Clock::now();
        pool.parallelFor(threads, [&](int b, int e) {
            for (int t = b; t < e; ++t)
                flops[static_cast<std::size_t>(t)] = lanes >= 16  ? chainsAvx512(steps, 1.0f + t)
                                                     : lanes >= 8 ? chainsAvx2(steps, 1.0f + t)
                                                                  : chainsSse(steps, 1.0f + t);
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
