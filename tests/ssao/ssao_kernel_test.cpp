#include <gtest/gtest.h>

#include "ssao/ssao_kernel.h"

#include <iostream>

using namespace obscura;
using namespace obscura::ssao;

TEST(SsaoKernel, RelaxedBeatsRandomOnSpacingAndDiscrepancy) {
    for (KernelShape shape : {KernelShape::Hemisphere, KernelShape::Sphere}) {
        for (int n : {8, 16, 32}) {
            double randDist = 0, relaxDist = 0, randDisc = 0, relaxDisc = 0;
            const int seeds = 5;
            for (int seed = 1; seed <= seeds; ++seed) {
                const auto start = randomDirections(n, shape, static_cast<std::uint64_t>(seed));
                const auto relaxed = relaxDirections(start, shape);
                randDist += minPairwiseDistance(start) / seeds;
                relaxDist += minPairwiseDistance(relaxed) / seeds;
                randDisc += capDiscrepancy(start, shape, 400) / seeds;
                relaxDisc += capDiscrepancy(relaxed, shape, 400) / seeds;
            }
            std::cout << (shape == KernelShape::Hemisphere ? "hemisphere" : "sphere") << " n=" << n
                      << ": min distance " << randDist << " -> " << relaxDist << ", cap discrepancy " << randDisc
                      << " -> " << relaxDisc << "\n";
            EXPECT_GT(relaxDist, 1.5 * randDist) << n;
            EXPECT_LT(relaxDisc, randDisc) << n;
        }
    }
}

// What the shaders read for n samples is relaxed for n: evener than the first n of a 32-sample
// kernel (what the modes read before), on the cap discrepancy of the directions they use.
TEST(SsaoKernel, TheShadersReadAKernelRelaxedForTheirSampleCount) {
    for (KernelShape shape : {KernelShape::Hemisphere, KernelShape::Sphere}) {
        for (int n : {8, 12, 16, 24}) {
            double prefix = 0, own = 0;
            const int seeds = 5;
            for (int seed = 1; seed <= seeds; ++seed) {
                const auto big = makeKernel(32, shape, static_cast<std::uint64_t>(seed));
                const auto read = kernelFor(n, 32, shape, static_cast<std::uint64_t>(seed));
                ASSERT_EQ(read.size(), 32u);
                for (int i = n; i < 32; ++i) EXPECT_EQ(read[static_cast<std::size_t>(i)], (Vec3{0, 0, 0}));
                prefix += capDiscrepancy({big.begin(), big.begin() + n}, shape, 400) / seeds;
                own += capDiscrepancy({read.begin(), read.begin() + n}, shape, 400) / seeds;
            }
            std::cout << (shape == KernelShape::Hemisphere ? "hemisphere" : "sphere") << " n=" << n
                      << ": cap discrepancy, first n of 32 " << prefix << ", relaxed for n " << own << "\n";
            EXPECT_LT(own, 0.8 * prefix) << n;
        }
    }
}

TEST(SsaoKernel, KernelStaysInsideTheUnitHemisphereAndIsSeeded) {
    const auto a = makeKernel(16, KernelShape::Hemisphere, 42);
    const auto b = makeKernel(16, KernelShape::Hemisphere, 42);
    const auto c = makeKernel(16, KernelShape::Hemisphere, 43);
    ASSERT_EQ(a.size(), 16u);
    double shortest = 1, longest = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_GE(a[i].z, 0.0);
        const double l = length(a[i]);
        shortest = std::min(shortest, l);
        longest = std::max(longest, l);
        EXPECT_EQ(a[i], b[i]);
    }
    EXPECT_GE(shortest, 0.1 - 1e-9);
    EXPECT_LE(longest, 1.0 + 1e-9);
    EXPECT_GT(longest - shortest, 0.5);  // radii really spread
    EXPECT_NE(a[0], c[0]);
}
