// GTAO's horizon search (Jimenez, Wu, Pesce, Jarabo 2016), shared by the gtao mode and the combined
// mode's small scale: kGtaoSlices screen-space directions (the per-pixel random vector, turned by
// 180/kGtaoSlices degrees each: no trigonometry for the directions), each the plane through V and
// that direction; along it the horizon is searched both ways out to the reach projected at the
// pixel's depth (sampleCount steps in all), the normal is projected into the slice, and the
// visibility between the two horizons is the paper's analytic inner integral (gtao.glsl).
// Needs ssao_common.glsl and gtao.glsl.
// 2 slices x 2 sides: at the default 32 samples, 8 steps a side in 4 screen directions, the
// horizon mode's 4 directions x 8 steps; the samples knob keeps its meaning (steps in all). Steps a
// side are what the error follows (room_a, 0.6 m truth, 1280x720 scored at 320x180: 4 steps a side
// .100 occluded-region MAE, 8 steps .070; 1 slice x 8 steps, the same 16 samples, .107: noisier;
// half resolution at 16 samples .100: resolution is not it). Spacing: linear; t^2 (XeGTAO's
// default) .117 / .083 at 16 / 32 samples, sqrt(t) .096 / .075.
const int kGtaoSlices = 2;
// The thickness heuristic (the paper's, for thin occluders): a sample below the horizon found so far
// pulls the horizon back by this share of the difference instead of not at all, so an occluder seen
// to end counts as thin. 0: the classic infinitely thick depth buffer, which is what the truth is
// (every brush and model solid). The decay is per step, so it grows with the sample count: 0.1 lost
// a horizon to 0.9^7 = 48 % behind 7 lower steps at 32 samples, and every indoor view was too light
// (room_b, the 0.6 m truth, 1280x720 scored at 320x180: .100 occluded-region MAE with 0.1, .086
// with 0; Sibenik's nave .093 / .077, its pillars .091 / .080; at 16 samples the two had differed
// by .0025 on six views). Kept as a knob for a scene of thin railings and foliage.
const float kThicknessBlend = 0.0;

// The distance falloff: the truth (engine_ext/ssao/ao_reference.h) counts an occluder anywhere
// inside the radius and nothing past it, and a wall's horizon is set by its samples near the radius.
// The weight falls linearly to 0 over the last 5 % of the radius only, so one sample does not flip
// in and out on a surface that crosses the radius. Chosen on six views the README does not report
// (pillars, low_angle, room_b, e3m4_start, e3m4_room_west, sibenik_pillars): a ramp over the last
// 5 / 10 / 25 % gave mean occluded-region MAE .127 / .132 / .148 there at the defaults (thickness
// 0); the horizon mode's 1 - d^2/r^2, which halves an occluder at 0.7 of the radius, was lighter
// still (.215 against .172 for the 25 % ramp, in an earlier build of this shader).
const float kFalloffShare = 0.05;

// The highest elevation (sin of the angle above the tangent plane) on one side, marched from the
// pixel out along stepUv: 0 is the hemisphere's rim. An elevation, not the angle from V, so a plane
// never occludes itself (engine_ext/ssao/gtao.h, horizonFromElevation, says why). Samples fade to
// the rim near the reach (kFalloffShare), and past the screen's border nothing is known.
float highestElevation(vec4 p, vec3 n, vec2 reachUv, int steps, float jitter, float reach)
{
    float best = 0.0;
    for (int s = 0; s < SSAO_MAX_SAMPLES; ++s) {
        if (s >= steps) break;
        float t = (float(s) + jitter) / float(steps);
        vec2 uv = vUv + reachUv * t;
        if (!onScreen(uv)) break;
        vec4 o = offsetTo(uv, p);
        if (o.w <= 0.0) continue;
        float falloff = clamp((reach - o.w) / (kFalloffShare * reach), 0.0, 1.0);
        if (falloff <= 0.0) continue;  // out of range: neither an occluder nor a sign that one ended
        float e = dot(o.xyz, n) * falloff;
        best = e > best ? e : mix(best, max(e, 0.0), kThicknessBlend);
    }
    return best;
}

// The cosine-weighted visibility (1 = open) of view-space point p with normal n by what lies within
// `reach` metres of it (the radius for the small scale; combined.frag also asks for its large one).
float gtaoVisibilityWithin(vec4 p, vec3 n, vec3 rnd, float reach)
{
    vec3 v = normalize(-p.xyz);
    vec2 radiusUv = 0.5 * projScale * reach / -p.z;
    int steps = max(int(sampleCount) / (2 * kGtaoSlices), 1);
    float jitter = rnd.z * 0.5 + 0.5;
    vec2 omega = normalize(rnd.xy + vec2(1e-4, 0.0));  // the slice's direction on the screen (uv)
    float seen = 0.0, open = 0.0;
    for (int i = 0; i < kGtaoSlices; ++i) {
        // The same direction in view space (uv's y runs down when render textures are flipped).
        vec3 d = vec3(omega.x, flipY > 0.5 ? -omega.y : omega.y, 0.0);
        vec3 ortho = d - dot(d, v) * v;              // the slice's axis beside V
        vec3 axis = normalize(cross(ortho, v));      // the slice plane's normal
        vec3 np = n - axis * dot(n, axis);           // the normal projected into the slice
        float npLength = length(np);
        float cosN = clamp(dot(np, v) / max(npLength, 1e-4), -1.0, 1.0);
        float angleN = (dot(ortho, np) < 0.0 ? -1.0 : 1.0) * acos(cosN);
        vec2 reachUv = omega * radiusUv;
        float h2 = gtaoHorizonFromElevation(highestElevation(p, n, reachUv, steps, jitter, reach), angleN, npLength, 1.0);
        float h1 = gtaoHorizonFromElevation(highestElevation(p, n, -reachUv, steps, jitter, reach), angleN, npLength, -1.0);
        seen += npLength * gtaoSliceIntegral(h1, h2, angleN);
        // The paper averages |n_p| a over the slices, which is 1 for an open plane only over many
        // slice directions (per slice 0.5 .. 1.41 for a plane seen 60 degrees off its normal; the
        // paper spreads its slices over 6 frames of temporal filtering, which this frame has not).
        // Dividing by the same slices' unoccluded integral (a ratio of two estimates over the same
        // slices, both of which tend to the paper's integrals) makes an open plane exactly 1 with 2
        // slices, instead of grey and white in the 4x4 noise's pattern, clamped at 1 before the blur
        // (room_b at full resolution, 32 samples: whole-frame MAE .018 with it, .029 without).
        open += npLength * gtaoSliceIntegral(angleN - kGtaoHalfPi, angleN + kGtaoHalfPi, angleN);
        omega = vec2(-omega.y, omega.x);  // 90 degrees = 180 / kGtaoSlices
    }
    return seen / max(open, 1e-4);
}
