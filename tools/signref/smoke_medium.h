// The participating medium of tools/signref: a uniform haze plus the smoke grids the game dumped
// (engine_ext/smoke/smoke_dump.h), with the sub-grid detail noise of
// shaders/smoke/smoke_march.glsl mirrored in double (smokeHash, smokeNoise, kNoiseTurn, `detail`):
// the same function, for the same medium.
#pragma once

#include "core/vec3.h"
#include "smoke/smoke_dump.h"

namespace obscura::signref {

// smoke_march.glsl's constants.
constexpr double kSmokeAlbedo[3] = {0.9, 0.9, 0.88};
constexpr double kSmokeCutoff = 0.004;  // densities below are skipped by the march (no smoke)

double smokeHash(const Vec3& p);
double smokeNoise(const Vec3& p);
Vec3 noiseTurn(const Vec3& v);  // kNoiseTurn * v (GLSL's column-major mat3)
// 0.55 + 0.6 noise(q 1.3) + 0.3 (noise(turn(q) 2.9) - 0.5), q = turn(p + (0, -0.3 time, 0)).
double smokeDetail(const Vec3& p, double time);

struct Medium {
    double haze = 0;                        // scattering per metre (albedo 1)
    const smoke::SmokeDump* smoke = nullptr;  // optional, not owned
    double hazeExtinction = -1;  // the haze's extinction per metre; < 0: `haze` (a physical haze);
                                 // 0: the game's thin-haze model (shaders/signs/sign_march.glsl)

    // Extinction (per metre) and the rgb scattering coefficient at p.
    void at(const Vec3& p, double& sigmaT, Vec3& sigmaS) const;
    // The optical depth from a to b: the haze's extinction exactly, the smoke's by points `step`
    // metres apart (at u in 0..1 of each step, jittered by the caller) over the part of the segment
    // inside the dumped grids' boxes; it stops once past `enough` (the light is gone).
    double opticalDepth(const Vec3& a, const Vec3& b, double step, double u, double enough = 30) const;
};

}  // namespace obscura::signref
