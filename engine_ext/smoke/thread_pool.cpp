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
}  // namespace

ThreadPool::ThreadPool(int threads) {
    if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    for (int t = 1; t < threads; ++t) workers_.emplace_back([this, t] { workerLoop(t); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (auto& w : workers_) w.join();
}

void ThreadPool::runChunk(int index) {
    const int n = threads();
    const int base = count_ / n, extra = count_ % n;
    const int begin = index * base + std::min(index, extra);
    const int end = begin + base + (index < extra ? 1 : 0);
    if (begin < end) (*job_)(begin, end);
}

void ThreadPool::parallelFor(int count, const std::function<void(int, int)>& fn) {
    if (count <= 0) return;
    if (workers_.empty() || count == 1) {
        fn(0, count);
        return;
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        job_ = &fn;
        count_ = count;
        pending_.store(static_cast<int>(workers_.size()), std::memory_order_relaxed);
        generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    runChunk(0);
    // Short spin first: most chunks finish within microseconds of each other.
    const auto spinUntil = std::chrono::steady_clock::now() + std::chrono::microseconds(200);
    while (pending_.load(std::memory_order_acquire) != 0 && std::chrono::steady_clock::now() < spinUntil) cpuRelax();
    if (pending_.load(std::memory_order_acquire) != 0) {
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [this] { return pending_.load(std::memory_order_acquire) == 0; });
    }
    job_ = nullptr;
}

void ThreadPool::workerLoop(int index) {
    unsigned seen = 0;
    for (;;) {
        // Spin briefly before sleeping: a step issues ~50 jobs back to back, and waking a thread
        // parked on the condition variable costs tens of microseconds each time (measured at 64^3:
        // ~0.6 ms of a 7 ms step). 100 us of polling after a job is nothing next to that.
        const auto spinUntil = std::chrono::steady_clock::now() + std::chrono::microseconds(100);
        while (generation_.load(std::memory_order_acquire) == seen && !stop_.load(std::memory_order_relaxed) &&
               std::chrono::steady_clock::now() < spinUntil) {
            cpuRelax();
        }
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
            if (stop_) return;
            seen = generation_.load(std::memory_order_relaxed);
        }
        runChunk(index);
        if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
            std::lock_guard<std::mutex> lock(mutex_);
            done_.notify_one();
        }
    }
}

}  // namespace obscura::smoke
