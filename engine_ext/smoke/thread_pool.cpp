#include "smoke/thread_pool.h"

#include <algorithm>
#include <chrono>

namespace obscura::smoke {
namespace {

void cpuRelax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();  // eases the spin on the sibling hyper-thread and the memory bus
#else
    std::this_thread::yield();
#endif
}

// Chunks per thread: enough that a thread the OS did not schedule leaves most of its share to
// the others (with one chunk each, the caller would wait for its chunk), few enough that a chunk
// of a 64^3 pass (62 planes: 8 chunks of ~8 planes on 2 threads) stays far longer than taking it
// (one compare-and-swap). A reasoned choice, not a measured optimum (the busy test machine's
// noise hides differences of a few per cent).
constexpr int kChunksPerThread = 4;
// Spinning before blocking: a solver step issues a few hundred jobs back to back, microseconds
// apart, and waking a blocked thread costs tens of microseconds; a worker polling 30 us catches
// the next job of the same step, and between steps (50 ms in the game) it blocks and gives the
// core back. With two competing processes on the 2 cores this pool ran 32^3 steps on 2 threads
// faster than on 1, where the old one (100 us spins after every job, fixed chunks) took 3x longer
// (README.md, "Thread pool").
constexpr std::int64_t kDefaultSpinNs = 30'000;

constexpr std::uint64_t kIndexBits = 20, kIndexMask = (std::uint64_t{1} << kIndexBits) - 1;
std::uint64_t pack(std::uint64_t generation, std::uint64_t chunks, std::uint64_t next) {
    return (generation << (2 * kIndexBits)) | (chunks << kIndexBits) | next;
}
std::uint64_t generationOf(std::uint64_t job) { return job >> (2 * kIndexBits); }
std::uint64_t chunksOf(std::uint64_t job) { return (job >> kIndexBits) & kIndexMask; }
std::uint64_t nextOf(std::uint64_t job) { return job & kIndexMask; }

using Clock = std::chrono::steady_clock;

// Spins until done() or `ns` nanoseconds passed; true if done.
template <class Done>
bool spinFor(std::int64_t ns, const Done& done) {
    if (done()) return true;
    const auto until = Clock::now() + std::chrono::nanoseconds(ns);
    for (;;) {
        for (int i = 0; i < 16; ++i) {
            cpuRelax();
            if (done()) return true;
        }
        if (Clock::now() >= until) return done();
    }
}

}  // namespace

ThreadPool::ThreadPool(int threads) : spinNs_(kDefaultSpinNs) {
    if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::min(threads, 256);
    for (int t = 1; t < threads; ++t) workers_.emplace_back([this] { workerLoop(); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (auto& w : workers_) w.join();
}

void ThreadPool::finishChunk() {
    if (remaining_.fetch_sub(1) == 1 && callerSleeping_.load()) {
        std::lock_guard<std::mutex> lock(mutex_);
        done_.notify_one();
    }
}

void ThreadPool::runChunks(std::uint64_t generation) {
    std::uint64_t job = job_.load();
    for (;;) {
        if (generationOf(job) != generation || nextOf(job) >= chunksOf(job)) return;
        // Success means job `generation` still had this chunk untaken, so the caller is still
        // inside parallelFor and fn_ / count_ are that job's (written before job_ was published).
        if (!job_.compare_exchange_weak(job, job + 1)) continue;  // job reloaded
        const std::int64_t chunks = static_cast<std::int64_t>(chunksOf(job)), index = static_cast<std::int64_t>(nextOf(job));
        const std::int64_t count = count_.load(std::memory_order_relaxed);
        const int begin = static_cast<int>(count * index / chunks), end = static_cast<int>(count * (index + 1) / chunks);
        if (begin < end) (*fn_.load(std::memory_order_relaxed))(begin, end);
        finishChunk();
        job = job_.load();
    }
}

void ThreadPool::parallelFor(int count, const std::function<void(int, int)>& fn) {
    if (count <= 0) return;
    if (workers_.empty() || count == 1) {
        fn(0, count);
        return;
    }
    const int chunks = std::min(count, threads() * kChunksPerThread);
    fn_.store(&fn, std::memory_order_relaxed);
    count_.store(count, std::memory_order_relaxed);
    remaining_.store(chunks);
    const std::uint64_t generation = (generationOf(job_.load()) + 1) & ((std::uint64_t{1} << 24) - 1);
    job_.store(pack(generation, static_cast<std::uint64_t>(chunks), 0));
    if (sleepingWorkers_.load() > 0) {
        { std::lock_guard<std::mutex> lock(mutex_); }
        wake_.notify_all();
    }
    runChunks(generation);
    // Chunks other threads took are running (a worker that took one is scheduled); wait for them,
    // spinning briefly, then blocked, which frees this core for a thread the OS has waiting.
    if (!spinFor(spinNs_.load(std::memory_order_relaxed), [this] { return remaining_.load() == 0; })) {
        std::unique_lock<std::mutex> lock(mutex_);
        callerSleeping_ = true;
        done_.wait(lock, [this] { return remaining_.load() == 0; });
        callerSleeping_ = false;
    }
}

void ThreadPool::workerLoop() {
    std::uint64_t seen = generationOf(job_.load());
    for (;;) {
        auto newJob = [&] { return stop_.load() || generationOf(job_.load()) != seen; };
        if (!spinFor(spinNs_.load(std::memory_order_relaxed), newJob)) {
            std::unique_lock<std::mutex> lock(mutex_);
            ++sleepingWorkers_;
            wake_.wait(lock, newJob);
            --sleepingWorkers_;
        }
        if (stop_.load()) return;
        seen = generationOf(job_.load());
        runChunks(seen);
    }
}

}  // namespace obscura::smoke
