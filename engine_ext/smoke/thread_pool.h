// A small fixed thread pool for the smoke solver: parallelFor splits a range into one contiguous
// chunk per thread (the calling thread takes chunk 0) and blocks until all are done. Which thread
// runs which chunk never changes a result in the solver: every cell's update depends only on its
// inputs, and reductions go through fixed per-plane partials (see smoke_solver.cpp).
#pragma once

#include <atomic>
#include <condition_variable>
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

    // Calls fn(begin, end) on [begin, end) sub-ranges of [0, count) that together cover it once.
    // Ranges are split evenly (count / threads, remainder to the first ones). Not re-entrant.
    void parallelFor(int count, const std::function<void(int, int)>& fn);

private:
    void workerLoop(int index);
    void runChunk(int index);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    const std::function<void(int, int)>* job_ = nullptr;
    int count_ = 0;
    std::atomic<unsigned> generation_{0};  // bumped per job; workers poll it before sleeping
    std::atomic<int> pending_{0};
    std::atomic<bool> stop_{false};
};

}  // namespace obscura::smoke
