// Creation, validation and the basic invariants of the smoke solver.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "smoke_test_levels.h"

using namespace obscura;
using namespace obscura::smoke;

TEST(SmokeBasic, RunsAndStaysValid) {
    const map::Level level = testlevels::closedRoom({-2.5, 0, -2.5}, {2.5, 3, 2.5});
    SmokeVolume vol = SmokeVolume::create(level, {}, {0, 0.1, 0}, testlevels::small(24));
    for (int i = 0; i < 60; ++i) {
        vol.step(1.0 / 30);
        std::string why;
        ASSERT_TRUE(vol.validate(&why)) << "step " << i << ": " << why;
    }
    EXPECT_GT(vol.totalDensity(), 0.5);
    std::cout << "total " << vol.totalDensity() << " div before " << vol.stats().divergenceBefore << " residual "
              << vol.stats().residual << " max div " << vol.maxDivergence() << " ms " << vol.stats().milliseconds << "\n";
}
