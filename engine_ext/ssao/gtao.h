// Ground-truth-based ambient occlusion, the math of one slice (Jimenez, Wu, Pesce, Jarabo,
// "Practical Real-Time Strategies for Accurate Indirect Occlusion", SIGGRAPH 2016 course / Activision
// tech report ATVI-TR-16-01). Plain C++, no OGRE: shaders/ssao/gtao.glsl mirrors it line for line
// and tests/ssao/gtao_test.cpp checks it against numeric integration.
//
// A slice is the plane through the view vector V and one screen-space direction. In it, angles are
// measured from V (positive towards the slice direction); the surface normal projected into the
// slice has length |n_p| and angle n. The cosine-weighted visibility of the slice between the two
// horizons h1 <= 0 <= h2 is |n_p| (a(h1) + a(h2)), with a the paper's analytic inner integral.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace obscura::ssao::gtao {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kHalfPi = kPi / 2;

// a(h) = 1/4 (-cos(2h - n) + cos n + 2h sin n) = the integral of cos(t - n) |sin t| dt from 0 to h
// (either sign of h): the cosine about the projected normal, |sin t| the slice's solid-angle measure.
inline double innerIntegral(double h, double n) {
    return 0.25 * (-std::cos(2.0 * h - n) + std::cos(n) + 2.0 * h * std::sin(n));
}

// A horizon angle clamped to the hemisphere about the projected normal (the paper's
// h1 = n + max(h1' - n, -pi/2), h2 = n + min(h2' - n, pi/2)).
inline double clampHorizon(double h, double n) { return n + std::clamp(h - n, -kHalfPi, kHalfPi); }

// The inner integral over the unoccluded arc h1 .. h2 of a slice (times |n_p| outside).
inline double sliceIntegral(double h1, double h2, double n) {
    return innerIntegral(clampHorizon(h1, n), n) + innerIntegral(clampHorizon(h2, n), n);
}

// The same for an unoccluded slice (horizons at n -+ pi/2): cos n + n sin n. Its average over all
// slice directions, weighted by |n_p|, is 1; one slice alone is not (0.5 .. 1.41 for a plane seen
// 60 degrees off its normal), which is why the shader divides by it (gtao.frag says why).
inline double openSliceIntegral(double n) { return sliceIntegral(n - kHalfPi, n + kHalfPi, n); }

// Where the normal lies in a slice: |n_p| and the signed angle n between n_p and V.
struct SliceNormal {
    double length = 0, angle = 0;
};
using Vec = std::array<double, 3>;
inline double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Vec axpy(double s, const Vec& x, const Vec& y) { return {s * x[0] + y[0], s * x[1] + y[1], s * x[2] + y[2]}; }
inline Vec normalized(const Vec& a) {
    const double l = std::sqrt(dot(a, a));
    return {a[0] / l, a[1] / l, a[2] / l};
}
// normal and view unit vectors (view: from the point towards the eye); direction: the slice's
// direction (view space, any vector not along V). The slice's positive side is direction's side.
inline SliceNormal sliceNormal(const Vec& normal, const Vec& view, const Vec& direction) {
    const Vec ortho = axpy(-dot(direction, view), view, direction);  // the slice's in-plane axis
    const Vec axis = normalized(cross(ortho, view));                  // the slice plane's normal
    const Vec np = axpy(-dot(normal, axis), axis, normal);
    SliceNormal s;
    s.length = std::sqrt(dot(np, np));
    if (s.length < 1e-12) return s;
    const double c = std::clamp(dot(np, view) / s.length, -1.0, 1.0);
    s.angle = (dot(ortho, np) < 0 ? -1.0 : 1.0) * std::acos(c);
    return s;
}

// The horizon angle of one side (side +1: towards the slice direction, -1: away) from the highest
// elevation found there, e = sin of the angle above the tangent plane (dot(H, N) of the unit vector
// to the sample). In the slice a direction at angle t has e = |n_p| cos(t - n), so the horizon lies
// acos(e / |n_p|) from the projected normal, on the side's side; e = 0 is the hemisphere's rim. The
// shader searches elevations, not angles from V: a sample rebuilt at its depth texel's centre lies
// up to half a texel off the slice, and on a plane seen at a grazing angle that turns into a horizon
// above the tangent line (the plane occluding itself) when measured from V, but not as an elevation
// above the tangent plane, which is zero for every point of the plane. Clamped to the side (h1 <= 0
// <= h2): an occluder over V itself leaves the slice closed.
inline double horizonFromElevation(double elevation, double n, double npLength, int side) {
    const double alpha = std::acos(std::clamp(elevation / std::max(npLength, 1e-9), 0.0, 1.0));
    return side > 0 ? std::max(n + alpha, 0.0) : std::min(n - alpha, 0.0);
}

// The multi-bounce fit (the paper's eq. 10, fitted to ground-truth interreflections): the
// visibility x of a surface of albedo rho, raised to what its inter-reflected light gives back.
// x' = max(x, ((x a + b) x + c) x); equals x for black, and 1 at x = 1 (to 5e-4) for any albedo.
inline double multiBounce(double x, double albedo) {
    const double a = 2.0404 * albedo - 0.3324;
    const double b = -4.7951 * albedo + 0.6417;
    const double c = 2.7552 * albedo + 0.6903;
    return std::max(x, ((x * a + b) * x + c) * x);
}

}  // namespace obscura::ssao::gtao
