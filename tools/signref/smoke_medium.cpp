// See smoke_medium.h. Line for line shaders/smoke/smoke_march.glsl, in double.
#include "signref/smoke_medium.h"

#include <cmath>

namespace obscura::signref {

namespace {
double fract(double x) { return x - std::floor(x); }
Vec3 fract(const Vec3& v) { return {fract(v.x), fract(v.y), fract(v.z)}; }
double mix(double a, double b, double t) { return a * (1 - t) + b * t; }
}  // namespace

double smokeHash(const Vec3& q) {
    Vec3 p = fract(q * 0.3183099 + Vec3{0.1, 0.1, 0.1});
    p *= 17.0;
    return fract(p.x * p.y * p.z * (p.x + p.y + p.z));
}

double smokeNoise(const Vec3& p) {
    const Vec3 i{std::floor(p.x), std::floor(p.y), std::floor(p.z)};
    Vec3 f = fract(p);
    f = {f.x * f.x * (3 - 2 * f.x), f.y * f.y * (3 - 2 * f.y), f.z * f.z * (3 - 2 * f.z)};
    auto h = [&](double dx, double dy, double dz) { return smokeHash(i + Vec3{dx, dy, dz}); };
    return mix(mix(mix(h(0, 0, 0), h(1, 0, 0), f.x), mix(h(0, 1, 0), h(1, 1, 0), f.x), f.y),
               mix(mix(h(0, 0, 1), h(1, 0, 1), f.x), mix(h(0, 1, 1), h(1, 1, 1), f.x), f.y), f.z);
}

Vec3 noiseTurn(const Vec3& v) {
    // mat3(0.00, 0.80, 0.60, -0.80, 0.36, -0.48, -0.60, -0.48, 0.64): its columns
    const Vec3 c0{0.00, 0.80, 0.60}, c1{-0.80, 0.36, -0.48}, c2{-0.60, -0.48, 0.64};
    return c0 * v.x + c1 * v.y + c2 * v.z;
}

double smokeDetail(const Vec3& p, double time) {
    const Vec3 q = noiseTurn(p + Vec3{0.0, -0.3 * time, 0.0});
    return 0.55 + 0.6 * smokeNoise(q * 1.3) + 0.3 * (smokeNoise(noiseTurn(q) * 2.9) - 0.5);
}

void Medium::at(const Vec3& p, double& sigmaT, Vec3& sigmaS) const {
    sigmaT = hazeExtinction < 0 ? haze : hazeExtinction;
    sigmaS = {haze, haze, haze};
    if (!smoke) return;
    double detail = -1;  // computed once, for the first volume with smoke at p
    for (const smoke::DumpVolume& v : smoke->volumes) {
        const double d = v.densityAt(p);
        if (d < kSmokeCutoff) continue;
        if (detail < 0) detail = smokeDetail(p, smoke->time);
        const double s = smoke->sigma * d * detail;
        sigmaT += s;
        sigmaS += Vec3{kSmokeAlbedo[0], kSmokeAlbedo[1], kSmokeAlbedo[2]} * s;
    }
}

}  // namespace obscura::signref
