// What the machine can do, measured in the benchmark's own run on the solver's thread pool:
// DRAM and L3 bandwidth (STREAM triad over arrays 24x / a third of the L3) and the peak float
// arithmetic (independent multiply and add chains on 4-, 8- or 16-float vectors, no FMA: the
// solver is built without contraction). Plus a CPU hog to oversubscribe the machine.
#pragma once

#include <cstddef>

namespace obscura::smoke {
class ThreadPool;
}

namespace smokebench {

// Best STREAM triad bandwidth (GB/s, STREAM's byte count: 3 arrays x 8 B per element) over
// `reps` repetitions of arrays of n doubles split over the pool's threads.
double triadGBs(obscura::smoke::ThreadPool& pool, std::size_t n, int reps);

// Peak GFLOP/s of multiplies and adds (one flop each) on all the pool's threads, on vectors of
// `lanes` floats: 16 (AVX-512), 8 (AVX2) or 4 (SSE2). The caller checks the CPU runs them.
double peakGflops(obscura::smoke::ThreadPool& pool, int lanes);

// The widest float vectors this CPU runs: 16 (AVX-512F), 8 (AVX2) or 4 (SSE2).
int widestLanes();

// Starts `n` child processes that spin until stopCompetitors() (or this process ends).
void startCompetitors(int n);
void stopCompetitors();

}  // namespace smokebench
