// See smoke_medium.h. Line for line shaders/smoke/smoke_march.glsl, in double.
#include "signref/smoke_medium.h"

#include <algorithm>
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

double Medium::opticalDepth(const Vec3& a, const Vec3& b, double step, double u, double enough) const {
    const Vec3 d = b - a;
    const double length = std::sqrt(dot(d, d));
    double tau = (hazeExtinction < 0 ? haze : hazeExtinction) * length;
    if (!smoke || !(length > 0)) return tau;
    // The part of a -> b (t in 0..1) inside any grid's box: outside them there is no smoke.
    double lo = 1, hi = 0;
    for (const smoke::DumpVolume& v : smoke->volumes) {
        const double size[3] = {v.nx * v.cellSize, v.ny * v.cellSize, v.nz * v.cellSize};
        const double o[3] = {v.origin.x, v.origin.y, v.origin.z}, s[3] = {a.x, a.y, a.z}, e[3] = {d.x, d.y, d.z};
        double t0 = 0, t1 = 1;
        for (int k = 0; k < 3 && t0 <= t1; ++k) {
            if (e[k] == 0) {
                if (s[k] < o[k] || s[k] > o[k] + size[k]) t1 = -1;
                continue;
            }
            const double ta = (o[k] - s[k]) / e[k], tb = (o[k] + size[k] - s[k]) / e[k];
            t0 = std::max(t0, std::min(ta, tb));
            t1 = std::min(t1, std::max(ta, tb));
        }
        if (t0 <= t1) lo = std::min(lo, t0), hi = std::max(hi, t1);
    }
    if (lo >= hi) return tau;
    const double base = hazeExtinction < 0 ? haze : hazeExtinction;
    const double span = (hi - lo) * length;
    const long steps = std::max(1L, static_cast<long>(std::ceil(span / step)));
    const double dt = span / static_cast<double>(steps);
    for (long k = 0; k < steps && tau < enough; ++k) {
        const Vec3 p = a + d * (lo + (static_cast<double>(k) + u) * dt / length);
        double sigmaT;
        Vec3 sigmaS;
        at(p, sigmaT, sigmaS);
        tau += (sigmaT - base) * dt;  // the smoke's share: the haze's is counted above
    }
    return tau;
}

}  // namespace obscura::signref
