// What the machine can do, measured in the benchmark's own run on the solver's thread pool:
// DRAM and L3 bandwidth (STREAM triad over arrays 24x / a third of the L3) and the peak float
// arithmetic (independent multiply and add chains on the widest vectors the solver uses, no FMA:
// the solver is built without contraction). Plus a CPU hog to oversubscribe the machine.
#pragma once

#include <cstddef>

namespace obscura::smoke {
class ThreadPool;
}

namespace smokebench {

// Best STREAM triad bandwidth (GB/s, STREAM's byte count: 3 arrays x 8 B per element) over
// `reps` repetitions of arrays of n doubles split over the pool's threads.
double triadGBs(obscura::smoke::ThreadPool& pool, std::size_t n, int reps);

// Peak GFLOP/s of multiplies and adds (one flop each) on all the pool's threads: 8-float AVX2
// vectors where `avx2`, else 4-float SSE2 ones.
double peakGflops(obscura::smoke::ThreadPool& pool, bool avx2);

// Starts `n` child processes that spin until stopCompetitors() (or this process ends).
void startCompetitors(int n);
void stopCompetitors();

}  // namespace smokebench
