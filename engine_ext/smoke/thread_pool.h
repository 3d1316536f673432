// A small fixed thread pool for the smoke solver. parallelFor cuts a range into a few contiguous
// chunks per thread; the calling thread and the workers take chunks from a shared counter until
// none is left, so a worker that the operating system has not scheduled (another process holds
// its core) never holds up the job: the caller runs its chunks. Waiting (workers for a job, the
// caller for chunks still running) spins for a bounded time, then blocks, so a busy machine gets
// the cores back. Which thread runs which chunk never changes a result in the solver: every cell's
// update depends only on its inputs, and reductions go through fixed per-plane partials.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace obscura::smoke {

class ThreadPool {
public:
    // threads <= 0: std::thread::hardware_concurrency() (at least 1).
    explicit ThreadPool(int threads = 0);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int threads() const { return static_cast<int>(workers_.size()) + 1; }

    // Calls fn(begin, end) on contiguous [begin, end) sub-ranges of [0, count) that together cover
    // it once, on any of the threads (the caller included), and returns when all are done. Not
    // re-entrant: fn must not call parallelFor.
    void parallelFor(int count, const std::function<void(int, int)>& fn);

    // Spin limit before blocking, microseconds (tests and the benchmark's comparisons).
    void setSpinMicroseconds(int us) { spinNs_.store(static_cast<std::int64_t>(us) * 1000, std::memory_order_relaxed); }

private:
    void workerLoop();
    // Takes and runs chunks of job `generation` while any is left.
    void runChunks(std::uint64_t generation);
    void finishChunk();

    std::vector<std::thread> workers_;
    // The job: (generation << 40) | (chunks << 20) | next chunk, changed by compare-and-swap only, so
    // a worker that wakes late can never take a chunk of a job that has moved on.
    std::atomic<std::uint64_t> job_{0};
    std::atomic<const std::function<void(int, int)>*> fn_{nullptr};
    std::atomic<int> count_{0};
    std::atomic<int> remaining_{0};  // chunks of the current job not finished yet
    std::atomic<int> sleepingWorkers_{0};
    std::atomic<bool> callerSleeping_{false};
    std::atomic<bool> stop_{false};
    std::atomic<std::int64_t> spinNs_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
};

}  // namespace obscura::smoke
