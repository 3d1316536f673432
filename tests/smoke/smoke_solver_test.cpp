// Solver properties: divergence after projection, determinism across thread counts, agreement
// with the scalar reference, mass conservation, robustness to extreme inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "smoke_test_levels.h"

using namespace obscura;
using namespace obscura::smoke;

namespace {

const map::Level& room() { return testlevels::standardRoom(); }

// A scripted run touching every code path: emitter, obstacles moving through, a bullet.
void script(SmokeVolume& vol, int steps, bool reference) {
    for (int i = 0; i < steps; ++i) {
        MovingObstacle player;
        player.centre = {-2.0 + 0.1 * i, 0.9, 0.5};
        player.velocity = {3.0, 0, 0};
        MovingObstacle crate;
        crate.shape = MovingObstacle::Shape::Box;
        crate.centre = {1.0, 0.4, -1.0 + 0.05 * i};
        crate.halfExtents = {0.3, 0.3, 0.3};
        crate.velocity = {0, 0, 1.5};
        vol.setMovingObstacles({player, crate});
        if (i == steps / 2) vol.carve({-3, 1.0, 0.1}, {1, 0.05, 0}, 6.0, 0.4);
        if (reference) vol.stepReference(1.0 / 30);
        else vol.step(1.0 / 30);
    }
}

bool bitwiseEqual(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

double maxAbsDiff(const std::vector<float>& a, const std::vector<float>& b) {
    double m = 0;
    for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, static_cast<double>(std::fabs(a[i] - b[i])));
    return m;
}

}  // namespace

// The projection makes the flow divergence-free up to the solver's residual; on the MAC grid
// the divergence measured afterwards IS that residual (same discrete operators), so a tight
// tolerance drives it to float round-off.
TEST(SmokeSolver, ConvergedProjectionIsDivergenceFree) {
    SmokeSettings st = testlevels::small(24);
    st.pressureTolerance = 1e-6;
    SmokeVolume vol = SmokeVolume::create(room(), {}, {0, 0.1, 0}, st);
    for (int i = 0; i < 30; ++i) vol.step(1.0 / 30);
    const double before = vol.stats().divergenceBefore, after = vol.maxDivergence();
    std::cout << "max |div| before " << before << " 1/s, after " << after << " 1/s (" << vol.stats().pressureIterations
              << " MGPCG iterations)\n";
    EXPECT_GT(before, 0.1);
    EXPECT_LT(after, 1e-5 * before + 1e-5);
    EXPECT_NEAR(vol.stats().residual, after, 1e-4) << "the reported residual is the divergence left";
}

// A whole grenade's life (18 s at the game's 20 Hz) in two rooms joined by a doorway, with a
// player walking through the door and back: after every step the divergence left is at most 1e-3
// of the divergence before the projection (or under the absolute floor of 1e-5 1/s), measured
// from the velocity itself. Both a closed pair of rooms (the singular Neumann problem) and the
// same rooms cut by the grid's open border.
TEST(SmokeSolver, ProjectionMeetsItsToleranceAllLife) {
    const map::Level level = testlevels::doorwayRooms();
    for (bool open : {false, true}) {
        // A 9 m box around a grenade at x = -0.75 holds both rooms and their walls: closed; a 6 m
        // box around one at x = -1.5 cuts the second room at x = 1.5: open.
        SmokeSettings st = testlevels::small(open ? 24 : 36);
        SmokeVolume vol = SmokeVolume::create(level, {}, {open ? -1.5 : -0.75, 0.05, 0.3}, st);
        ASSERT_EQ(vol.state().regionOpen, open);
        double worst = 0, sum = 0, floorSteps = 0;
        int steps = 0, maxIterations = 0, iterations = 0;
        while (!vol.finished()) {
            MovingObstacle player;
            player.shape = MovingObstacle::Shape::Box;
            const double t = vol.age(), x = 2.5 * std::sin(0.5 * t);  // through the door and back
            player.centre = {x, 0.9, 0.0};
            player.halfExtents = {0.3, 0.9, 0.3};
            player.velocity = {1.25 * std::cos(0.5 * t), 0, 0};
            vol.setMovingObstacles({player});
            vol.step(0.05);
            const SmokeStats& s = vol.stats();
            const double after = vol.maxDivergence();
            const double relative = s.divergenceBefore > 0 ? after / s.divergenceBefore : 0.0;
            if (after > 1e-5) {
                worst = std::max(worst, relative);
                sum += relative;
            } else {
                ++floorSteps;
            }
            ASSERT_TRUE(relative <= 1e-3 || after <= 1e-5)
                << "t " << vol.age() << ": before " << s.divergenceBefore << " after " << after << " (" << s.pressureIterations << " iterations)";
            EXPECT_LE(s.worstRelativeResidual, 1e-3) << "every substep, as the solver saw it";
            ++steps;
            iterations += s.pressureIterationsTotal;
            maxIterations = std::max(maxIterations, s.pressureIterations);
        }
        std::cout << (open ? "open" : "closed") << " rooms, " << steps << " steps: relative divergence left mean "
                  << sum / std::max(1.0, steps - floorSteps) << ", worst " << worst << " (" << floorSteps
                  << " steps under 1e-5 1/s); MGPCG iterations per step " << static_cast<double>(iterations) / steps
                  << ", most in one substep " << maxIterations << "\n";
    }
}

TEST(SmokeSolver, SameResultForAnyThreadCount) {
    for (int resolution : {24, 21}) {
        SmokeSettings st = testlevels::small(resolution, 1);
        SmokeVolume one = SmokeVolume::create(room(), {}, {0, 0.1, 0}, st);
        st.threads = 2;
        SmokeVolume two = SmokeVolume::create(room(), {}, {0, 0.1, 0}, st);
        st.threads = 5;  // more threads than cores and an uneven split of the planes
        SmokeVolume five = SmokeVolume::create(room(), {}, {0, 0.1, 0}, st);
        script(one, 40, false);
        script(two, 40, false);
        script(five, 40, false);
        for (const SmokeVolume* v : {&two, &five}) {
            EXPECT_TRUE(bitwiseEqual(one.state().density, v->state().density)) << v->threads() << " threads";
            EXPECT_TRUE(bitwiseEqual(one.state().temperature, v->state().temperature));
            EXPECT_TRUE(bitwiseEqual(one.state().u, v->state().u));
            EXPECT_TRUE(bitwiseEqual(one.state().v, v->state().v));
            EXPECT_TRUE(bitwiseEqual(one.state().w, v->state().w));
            EXPECT_TRUE(bitwiseEqual(one.state().pressure, v->state().pressure));
            EXPECT_EQ(one.stats().residual, v->stats().residual);
        }
    }
}

// The AVX2 build and the baseline (SSE2) build of the optimised path: same bits, so a replay
// recorded on one CPU plays the same on another. Odd sizes too: rows end in a vector that
// overlaps the one before it. Where the CPU has no AVX2 both volumes run the baseline (said).
TEST(SmokeSolver, SameResultForEitherVectorBuild) {
    if (!avx2PathAvailable()) std::cout << "this CPU has no AVX2: both runs take the baseline build\n";
    for (int resolution : {24, 19}) {
        SmokeSettings st = testlevels::small(resolution, 2);
        SmokeVolume best = SmokeVolume::create(room(), {}, {0, 0.1, 0}, st);
        st.vectorIsa = VectorIsa::Baseline;
        SmokeVolume baseline = SmokeVolume::create(room(), {}, {0, 0.1, 0}, st);
        script(best, 40, false);
        script(baseline, 40, false);
        EXPECT_GT(best.totalDensity(), 1.0) << "the script made smoke";
        EXPECT_TRUE(bitwiseEqual(best.state().density, baseline.state().density)) << resolution;
        EXPECT_TRUE(bitwiseEqual(best.state().temperature, baseline.state().temperature));
        EXPECT_TRUE(bitwiseEqual(best.state().u, baseline.state().u));
        EXPECT_TRUE(bitwiseEqual(best.state().v, baseline.state().v));
        EXPECT_TRUE(bitwiseEqual(best.state().w, baseline.state().w));
        EXPECT_TRUE(bitwiseEqual(best.state().pressure, baseline.state().pressure));
    }
}

// Optimised vs scalar reference. Both evaluate every value with the same kernels in the same
// order, so they agree exactly in practice; the stated tolerance (1e-5 of the field's scale)
// leaves room for a compiler contracting differently in the two loops.
TEST(SmokeSolver, MatchesScalarReference) {
    // An odd resolution too: the optimised red-black sweep stores the colours apart by row halves.
    for (int resolution : {24, 21}) {
        for (PressureSolver solver : {PressureSolver::MultigridCG, PressureSolver::RedBlackGaussSeidel, PressureSolver::Jacobi}) {
            SmokeSettings st = testlevels::small(resolution, 2);
            st.pressureSolver = solver;
            SmokeVolume fast = SmokeVolume::create(room(), {}, {0, 0.1, 0}, st);
            SmokeVolume ref = SmokeVolume::create(room(), {}, {0, 0.1, 0}, st);
            script(fast, 30, false);
            script(ref, 30, true);
            const double dd = maxAbsDiff(fast.state().density, ref.state().density);
            const double du = std::max({maxAbsDiff(fast.state().u, ref.state().u), maxAbsDiff(fast.state().v, ref.state().v),
                                        maxAbsDiff(fast.state().w, ref.state().w)});
            const char* name = solver == PressureSolver::Jacobi ? "Jacobi" : solver == PressureSolver::MultigridCG ? "MGPCG" : "RBGS";
            std::cout << resolution << "^3 " << name << ": max |density diff| " << dd
                      << ", max |velocity diff| " << du << "\n";
            EXPECT_LE(dd, 1e-5 * 1.0);  // densities reach ~1
            EXPECT_LE(du, 1e-5 * 5.0);  // speeds reach a few m/s
            EXPECT_NEAR(fast.stats().residual, ref.stats().residual, 1e-6 + 1e-4 * ref.stats().residual);
        }
    }
}

// Closed room, no modelled decay, the emitter done: the flux-form transport moves smoke only
// across faces, what one cell loses its neighbour gains, so the total stays what it was up to
// float rounding (measured: ~1e-7 over 3 s). Stated bound: 1 % per second; the test asks 1e-4
// over 3 s, so it fails on any real leak or source.
TEST(SmokeSolver, TransportConservesMass) {
    SmokeSettings st = testlevels::small(24);
    st.emitTime = 0.5;
    st.densityDissipation = 0;
    st.fadeTime = 0;
    SmokeVolume vol = SmokeVolume::create(room(), {}, {0, 0.1, 0}, st);
    while (vol.emitting()) vol.step(1.0 / 30);
    const double m0 = vol.totalDensity();
    double worstStep = 0;
    for (int i = 0; i < 90; ++i) {
        const double before = vol.totalDensity();
        vol.step(1.0 / 30);
        worstStep = std::max(worstStep, std::fabs(vol.totalDensity() - before) / before);
    }
    const double m1 = vol.totalDensity();
    std::cout << "mass " << m0 << " -> " << m1 << " over 3 s (" << 100.0 * (m1 - m0) / m0 / 3.0 << " %/s; worst step "
              << worstStep << ")\n";
    EXPECT_GT(m0, 0.9 * st.emitSmokeDensity * st.emitGasRate * st.emitTime) << "the gas's smoke is in the room";
    EXPECT_NEAR(m1, m0, 1e-4 * m0);
}

TEST(SmokeSolver, NeverNanOrInfWithExtremeInputs) {
    SmokeSettings st = testlevels::small(20);
    st.emitSmokeDensity = 1e30;
    st.emitTemperature = 1e30;
    st.buoyancy = 1e10;
    st.vorticity = 1e6;
    st.emitGasRate = 1e6;
    st.emitVelocity = {1e20, -1e20, 1e20};
    SmokeVolume vol = SmokeVolume::create(room(), {}, {0, 0.1, 0}, st);
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    const double dts[] = {1.0 / 30, 1e9, -1.0, nan, inf, 0.0, 1e-30, 0.1};
    for (int round = 0; round < 4; ++round)
        for (double dt : dts) {
            MovingObstacle o;
            o.centre = {0, 1, 0};
            o.velocity = {1e300, nan, -1e300};
            MovingObstacle bad;
            bad.centre = {nan, 0, 0};
            MovingObstacle huge;
            huge.radius = 1e300;
            vol.setMovingObstacles({o, bad, huge, MovingObstacle{}});
            vol.carve({0, 1, -3}, {0, 0, 1}, 1e300, 0.5, 1e30);
            vol.carve({nan, 0, 0}, {0, 0, 0}, nan, nan);
            vol.step(dt);
            vol.computeTransmittance({0.3, 1, 0.2});
            std::string why;
            ASSERT_TRUE(vol.validate(&why)) << "dt " << dt << ": " << why;
            EXPECT_TRUE(std::isfinite(vol.sampleDensity({0, 1, 0})));
            EXPECT_TRUE(std::isfinite(vol.stats().residual));
        }
    vol.setMovingObstacles({});
    for (int i = 0; i < 10; ++i) vol.stepReference(0.05);
    std::string why;
    EXPECT_TRUE(vol.validate(&why)) << why;
}
