// GTAO's slice math (engine_ext/ssao/gtao.h, mirrored by shaders/ssao/gtao.glsl) against numeric
// integration of the cosine-weighted visibility: one slice, a whole open hemisphere, and the foot of
// an infinite wall (true visibility 1/2); and the multi-bounce fit's endpoints.
#include <gtest/gtest.h>

#include "core/rng.h"
#include "ssao/gtao.h"

#include <cmath>

using namespace obscura::ssao::gtao;

namespace {
// The integral of cos(t - n)^+ |sin t| over h1 .. h2 by the midpoint rule: what the inner integral
// claims in closed form (the clamped cosine: directions below the surface carry no weight).
double numericSlice(double h1, double h2, double n, int steps = 20000) {
    double sum = 0;
    const double dt = (h2 - h1) / steps;
    for (int i = 0; i < steps; ++i) {
        const double t = h1 + (i + 0.5) * dt;
        sum += std::max(std::cos(t - n), 0.0) * std::abs(std::sin(t)) * dt;
    }
    return sum;
}

Vec randomUnit(obscura::Rng& rng) {
    for (;;) {
        const Vec v{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        const double l2 = dot(v, v);
        if (l2 > 0.01 && l2 <= 1) return normalized(v);
    }
}

// The cosine-weighted visibility of a point with normal `normal`, seen along `view`, estimated as
// GTAO does (slices around V, each with its two horizons) with `slices` evenly spread slices;
// horizonOf(direction in the slice, side) gives the horizon angle of that side (h >= 0 for +1).
template <class Horizon>
double slicedVisibility(const Vec& normal, const Vec& view, int slices, Horizon horizonOf) {
    // Two axes perpendicular to V: the slice directions turn in the plane they span.
    const Vec e1 = normalized(cross(view, std::abs(view[0]) < 0.9 ? Vec{1, 0, 0} : Vec{0, 1, 0}));
    const Vec e2 = cross(view, e1);
    double sum = 0;
    for (int i = 0; i < slices; ++i) {
        const double phi = kPi * (i + 0.5) / slices;
        const Vec d = axpy(std::cos(phi), e1, Vec{std::sin(phi) * e2[0], std::sin(phi) * e2[1], std::sin(phi) * e2[2]});
        const SliceNormal s = sliceNormal(normal, view, d);
        sum += s.length * sliceIntegral(horizonOf(d, -1, s.angle), horizonOf(d, +1, s.angle), s.angle);
    }
    return sum / slices;
}
}  // namespace

TEST(Gtao, InnerIntegralMatchesNumericIntegration) {
    obscura::Rng rng(7);
    for (int i = 0; i < 200; ++i) {
        const double n = rng.uniform(-kHalfPi, kHalfPi);
        // Horizons inside the hemisphere about the projected normal, one on each side of V.
        const double h1 = rng.uniform(n - kHalfPi, std::min(0.0, n + kHalfPi));
        const double h2 = rng.uniform(std::max(0.0, n - kHalfPi), n + kHalfPi);
        EXPECT_NEAR(sliceIntegral(h1, h2, n), numericSlice(h1, h2, n), 1e-6) << "n " << n << " h " << h1 << " " << h2;
    }
}

TEST(Gtao, HorizonsAreClampedToTheNormalsHemisphere) {
    // A horizon below the surface (past n -+ pi/2) counts as the surface itself: nothing more is seen.
    const double n = 0.4;
    EXPECT_DOUBLE_EQ(clampHorizon(-kPi, n), n - kHalfPi);
    EXPECT_DOUBLE_EQ(clampHorizon(kPi, n), n + kHalfPi);
    EXPECT_DOUBLE_EQ(clampHorizon(0.1, n), 0.1);
    EXPECT_NEAR(openSliceIntegral(n), numericSlice(n - kHalfPi, n + kHalfPi, n), 1e-6);
    EXPECT_NEAR(openSliceIntegral(0.0), 1.0, 1e-12);
}

TEST(Gtao, HorizonFromElevationRecoversTheSlicesAngle) {
    // A direction in the slice at angle t from V, between the projected normal and the rim on its
    // side, has elevation |n_p| cos(t - n) above the tangent plane; the angle comes back from it.
    obscura::Rng rng(5);
    for (int i = 0; i < 200; ++i) {
        const double n = rng.uniform(-1.5, 1.5), len = rng.uniform(0.1, 1.0);
        for (int side : {-1, +1}) {
            const double t = n + side * rng.uniform(0.0, static_cast<float>(kHalfPi));
            const double e = len * std::cos(t - n);
            const double expected = side > 0 ? std::max(t, 0.0) : std::min(t, 0.0);
            EXPECT_NEAR(horizonFromElevation(e, n, len, side), expected, 1e-6) << n << " " << t;
        }
    }
    // Nothing above the tangent plane: the rim, n -+ pi/2.
    EXPECT_NEAR(horizonFromElevation(0.0, 0.3, 0.8, +1), 0.3 + kHalfPi, 1e-12);
    EXPECT_NEAR(horizonFromElevation(-0.2, 0.3, 0.8, -1), 0.3 - kHalfPi, 1e-12);
}

TEST(Gtao, AnOpenSurfaceIsFullyVisibleFromEveryView) {
    // Slices spread over all directions: sum of |n_p| (a(h1) + a(h2)) / slices -> 1 with the horizons
    // at the hemisphere's rim, for any normal facing the eye.
    obscura::Rng rng(11);
    const auto open = [](const Vec&, int side, double n) { return n + side * kHalfPi; };
    for (int i = 0; i < 50; ++i) {
        const Vec view = randomUnit(rng);
        Vec normal = randomUnit(rng);
        if (dot(normal, view) < 0.05) continue;
        EXPECT_NEAR(slicedVisibility(normal, view, 2000, open), 1.0, 1e-3);
    }
}

TEST(Gtao, TheFootOfAnInfiniteWallIsHalfVisible) {
    // Floor normal +y, the wall the half-space x > 0 through the point: every direction with x > 0
    // is blocked, the cosine-weighted visibility is exactly 1/2. Each slice's horizons are found by
    // stepping out from V along the slice until a direction is blocked or goes below the floor.
    const Vec normal{0, 1, 0};
    for (const Vec& eye : {Vec{-1, 1, 0.3}, Vec{-0.4, 0.8, 1}, Vec{-2, 0.5, -1}}) {
        const Vec view = normalized(eye);
        const auto wall = [&](const Vec& d, int side, double n) {
            const Vec ortho = normalized(axpy(-dot(d, view), view, d));
            const double limit = n + side * kHalfPi;
            const int steps = 8000;
            for (int k = 1; k <= steps; ++k) {
                const double t = side * kPi * k / steps;
                const Vec w = axpy(std::cos(t), view, Vec{std::sin(t) * ortho[0], std::sin(t) * ortho[1], std::sin(t) * ortho[2]});
                if (w[0] > 0 || side * (t - limit) > 0) return t - side * kPi / steps;
            }
            return limit;
        };
        EXPECT_NEAR(slicedVisibility(normal, view, 720, wall), 0.5, 2e-3) << eye[0] << " " << eye[1] << " " << eye[2];
    }
}

TEST(Gtao, MultiBounceFitKeepsItsEndpoints) {
    for (double albedo : {0.0, 0.3, 0.6, 0.9}) {
        EXPECT_NEAR(multiBounce(0.0, albedo), 0.0, 1e-12);
        EXPECT_NEAR(multiBounce(1.0, albedo), 1.0, 1e-3);  // the fit's coefficients: a + b + c = 0.9996 + 0.0005 albedo
        for (double x = 0.05; x < 1.0; x += 0.05) EXPECT_GE(multiBounce(x, albedo), x);  // light is only given back
    }
    // Black gives nothing back; brighter surfaces give back more.
    for (double x = 0.05; x < 1.0; x += 0.05) {
        EXPECT_DOUBLE_EQ(multiBounce(x, 0.0), x);
        EXPECT_GT(multiBounce(x, 0.8), multiBounce(x, 0.4));
    }
    // The coefficients as the paper prints them (a typo shows here): by hand, x 0.5, albedo 0.6.
    EXPECT_NEAR(multiBounce(0.5, 0.6), 0.72435, 1e-4);
}
