// The ground truth for the back-lit signs' light shafts (issue 15): the single-scattering integral
// the game's volumetric pass estimates, in double precision, by brute force.
//
//   L(pixel) = mean over the pixel's area of
//              integral_0^tmax T(t) sigma_s(p) sum_signs phase(cos theta) E(p) dt,   p = eye + t dir
//
//   tmax      the view ray's first hit on the level's triangles (RayScene), or `far`
//   E(p)      lightColour x intensity x share(p) x cone(p) x window(d) / max(d, R)^2 (sign_light.h),
//             share(p) = the part of the lamp's sphere p sees through the plate: `lampSamples`
//             directions uniform in the solid angle of the sphere seen from p, each traced to the
//             plate's plane (open where openDistance > 0 and inside the plate: letters and holes)
//             and through the level (an occlusion ray from p to the plate: walls and props; the
//             plate and housing are not in the level's triangles). Not throughSign's disc formula.
//   phase     Henyey-Greenstein x pi, g = 0.3, cos theta = dot(dir, normalize(p - lamp))
//             (shaders/smoke/smoke_march.glsl's smokePhase, kSmokeG)
//   medium    a uniform haze (sigma_s = sigma_t = haze, albedo 1) plus the dumped smoke grids:
//             sigma_t += smokeSigma x density(p) x detail(p, time), albedo kSmokeAlbedo
//             (smoke_medium.h: smoke_march.glsl's noise, in double)
//   T(t)      exp(-integral sigma_t)
//   E(p) is dimmed by the medium on its way from the lamp: x exp(-integral sigma_t, p -> lamp)
//             (shadowStep; the law's light too)
//
// Along the ray: steps of `step` metres with one jittered point each (stratified), the medium
// and the light constant over a step, integrated exactly over it: T (sigma_s / sigma_t)
// (1 - exp(-sigma_t dt)) x source (exact for a uniform haze and light). Pixels: `spp` stratified,
// jittered positions. Every pixel has its own Rng stream: any thread count gives the same image.
#pragma once

#include "core/pfm.h"
#include "core/rng.h"
#include "core/vec3.h"
#include "raytrace/camera_pose.h"
#include "raytrace/ray_scene.h"
#include "signs/sign_light.h"
#include "signref/smoke_medium.h"

#include <cstdint>
#include <vector>

namespace obscura::signref {

// A sign as the reference sees it: its entity, its mask and its holes.
struct SignLight {
    signs::SignSpec spec;
    signs::SignMask mask;
    std::vector<signs::Hole> holes;
};

struct ShaftOptions {
    int spp = 4;            // view rays a pixel (stratified over its area)
    double step = 0.02;     // metres between the points along a ray
    int lampSamples = 16;   // directions towards the lamp's sphere at each point
    double far = 50;        // metres: where a ray that hits nothing stops
    bool geometry = true;   // trace the level between each point and the plate (Vgeom)
    // Skip the lamp's samples at a point whose lamp footprint on the plate (a bound, with a
    // quarter to spare) lies wholly outside the plate or where the mask's distance says no letter
    // or hole is within 1.5x its size (the bilinear field changes by at most sqrt(2) a metre):
    // the samples would all be shut. Off: every point is sampled (the tests compare the two).
    bool cull = true;
    // The game's law instead of the truth: lawIrradiance (signIrradiance, throughSign's disc
    // formula, and one occlusion ray to the lamp's centre) for E. Not the truth: it shows how much
    // of a game figure is the law's and how much the estimator's (README).
    bool law = false;
    // The lamp's light dimmed by the medium between the point and the lamp (the smoke, and a
    // physical haze): exp(-Medium::opticalDepth), points this many metres apart; 0: not dimmed
    // (the truth before the game's smoke shadowed its lamps). The cloud's cells are 0.25 m.
    double shadowStep = 0.05;
    std::uint64_t seed = 1;
};

// The sign's light at p before the plate and the level: lightColour x intensity x cone(p) x
// window(d) / max(d, lightRadius)^2, the factors signIrradiance multiplies throughSign by
// (sign_light.h); 0 where p is not in front of the plate.
Vec3 unshadowedIrradiance(const signs::SignSpec& sign, const Vec3& p);

// signIrradiance (the header's law) at p, and 0 where the level blocks the segment from p to
// the plate on the way to the lamp's centre (when `scene` is given).
Vec3 lawIrradiance(const SignLight& sign, const RayScene* scene, const Vec3& p);

// The share (0..1) of the lamp's sphere seen from p through the plate, `samples` stratified
// directions (at least 1), and through the level when `scene` is given.
double lampShare(const SignLight& sign, const RayScene* scene, const Vec3& p, int samples, Rng& rng);

// HG x pi (smoke_march.glsl's smokePhase).
double phaseHG(double cosTheta, double g);
constexpr double kShaftG = 0.3;  // smoke_march.glsl's kSmokeG

class ShaftReference {
public:
    // `scene` and `medium` must outlive the reference.
    ShaftReference(const RayScene& scene, std::vector<SignLight> signs, const Medium& medium);

    // The in-scattered radiance along eye + t dir, 0 <= t < tmax (one ray, its own jitter from rng).
    Vec3 alongRay(const Vec3& eye, const Vec3& dir, double tmax, const ShaftOptions& opt, Rng& rng) const;
    // One pixel of a width x height view (pixel-area average of `spp` rays).
    Vec3 pixel(const CameraPose& pose, int width, int height, int x, int y, const ShaftOptions& opt) const;
    FloatImage render(const CameraPose& pose, int width, int height, const ShaftOptions& opt, int threads) const;

    const std::vector<SignLight>& signs() const { return signs_; }

private:
    double lampShareCulled(const SignLight& sign, const Vec3& p, const ShaftOptions& opt, Rng& rng) const;

    const RayScene& scene_;
    std::vector<SignLight> signs_;
    const Medium& medium_;
};

// ---- Edge widths ----

// The 10-90 % width of a profile v(s) (s increasing): from its 50 % crossing (between its min and
// max), outwards to where it crosses 10 % and 90 %, linearly interpolated. False when the profile
// is flat or does not cross both levels.
bool width1090(const std::vector<double>& s, const std::vector<double>& v, double& width, double& s50);

// The 10-90 % width of discEdgeFraction's profile, as a share of the disc's diameter 2r.
double discEdge1090Share();

struct EdgeMeasure {
    std::vector<double> s;      // metres along from -> to
    std::vector<double> share;  // the lamp's share at each point (sampled truth)
    bool found = false;
    double width1090 = 0;       // metres along the line
    double b = 0, a = 0;        // at the 50 % point: in front of the plate, the lamp behind it
    double penumbra = 0;        // 2 R b / a
    double penumbra1090 = 0;    // its 10-90 % equivalent: discEdge1090Share() x 2 R b / a
    // A sphere seen at an angle psi off the plate's normal (cosAxis = cos psi, from the lamp to the
    // 50 % point) casts a wider penumbra across the tilt than throughSign's disc parallel to the
    // plate: its footprint on the plate is an ellipse, r / cos psi along the tilt, r across it.
    // The 10-90 % width of an edge across the tilt: penumbra1090 / cos psi.
    double cosAxis = 1;
    double sphere1090 = 0;
};

// The lamp's share along the receiver points from -> to (`points` of them) with `lampSamples`
// directions each (geometry through `scene` when given), and its 10-90 % width against the
// analytic penumbra.
EdgeMeasure measureEdge(const SignLight& sign, const RayScene* scene, const Vec3& from, const Vec3& to, int points,
                        int lampSamples, std::uint64_t seed);

// ---- Comparison with the game's dump ----

struct ShaftError {
    double rmse = 0, rmseOff = 0, meanRef = 0, maxRef = 0;
    std::size_t pixels = 0;
};
// Over every pixel and the three channels (rgb); rmseOff: an all-zero image (no shafts). Throws
// std::runtime_error when the sizes differ or the game's image holds a non-finite value.
ShaftError compareShafts(const FloatImage& ref, const FloatImage& game);

}  // namespace obscura::signref
