// The smoke solver's thread pool: every index exactly once for any thread and chunk count, also
// when the pool has more threads than the machine has cores.
#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "smoke/thread_pool.h"

using namespace obscura::smoke;

TEST(SmokeThreadPool, EveryIndexOnceForAnyThreadCount) {
    for (int threads : {1, 2, 3, 8}) {
        ThreadPool pool(threads);
        EXPECT_EQ(pool.threads(), threads);
        for (int count : {0, 1, 2, 7, 62, 1000}) {
            std::vector<std::atomic<int>> hits(static_cast<std::size_t>(count));
            for (auto& h : hits) h = 0;
            for (int round = 0; round < 20; ++round)  // back-to-back jobs, as a solver step issues them
                pool.parallelFor(count, [&](int b, int e) {
                    EXPECT_LT(b, e);
                    for (int i = b; i < e; ++i) ++hits[static_cast<std::size_t>(i)];
                });
            for (int i = 0; i < count; ++i) ASSERT_EQ(hits[static_cast<std::size_t>(i)].load(), 20) << threads << " threads, index " << i;
        }
    }
}

// Workers that block at once (no spinning) and a pool larger than the machine: still complete.
TEST(SmokeThreadPool, BlockingWorkersAndOversubscription) {
    ThreadPool pool(16);
    pool.setSpinMicroseconds(0);
    std::atomic<long> sum{0};
    for (int round = 0; round < 200; ++round) pool.parallelFor(64, [&](int b, int e) { sum += e - b; });
    EXPECT_EQ(sum.load(), 200 * 64);
}
