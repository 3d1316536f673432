#version 330 core
// Ground-truth-based AO (Jimenez, Wu, Pesce, Jarabo, "Practical Real-Time Strategies for Accurate
// Indirect Occlusion", SIGGRAPH 2016): the cosine-weighted visibility of the hemisphere, integrated
// per slice. Each of kGtaoSlices screen-space directions (the per-pixel random vector, turned by
// 180/kGtaoSlices degrees each: no trigonometry for the directions) is the plane through V and that
// direction; along it the horizon is searched both ways out to the projected radius
// (sampleCount steps in all), the normal is projected into the slice, and the visibility between
// the two horizons is the paper's analytic inner integral (gtao.glsl, engine_ext/ssao/gtao.h).
in vec2 vUv;
out vec4 fragColour;
#include "ssao_common.glsl"
#include "gtao.glsl"
uniform sampler2D gbufferAlbedo;  // gamma albedo (the frame's G-buffer), for the multi-bounce fit
uniform float visibilityPower;    // intensity / its default (ssao_compositor.cpp): 1 = the visibility itself
uniform float multiBounce;        // 1: the multi-bounce fit with this pixel's albedo (media/ssao/ssao.program says why it is off)
// 2 slices x 2 sides: at the default 16 samples, 4 steps a side in 4 screen directions, the
// horizon mode's 4 directions x 4 steps; the samples knob keeps its meaning (steps in all).
const int kGtaoSlices = 2;
// The thickness heuristic (the paper's, for thin occluders): a sample below the horizon found so far
// pulls the horizon back by this share of the difference instead of not at all, so an occluder seen
// to end (the surface behind it lower again within the radius) counts as thin and occludes less than
// a wall; samples past the radius are skipped, not taken as the occluder's end. 0.1: a horizon behind
// which all the remaining steps (3 at 16 samples) fall back keeps 0.9^3 = 73 % of its height, so a
// 0.25 m pillar, a step or two wide at the radius, stays an occluder, only less of one; 0 is the
// classic infinitely thick depth buffer. Not tuned: the truth's views have few thin occluders and
// every mode is too light there, so any thickness can only cost on the table (0.1 against 0:
// +0.0025 mean occluded-region MAE on the six tuning views named below).
const float kThicknessBlend = 0.1;

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
// the rim near the radius (kFalloffShare), and past the screen's border nothing is known.
float highestElevation(vec4 p, vec3 n, vec2 stepUv, int steps, float jitter)
{
    float best = 0.0;
    for (int s = 0; s < SSAO_MAX_SAMPLES; ++s) {
        if (s >= steps) break;
        vec2 uv = vUv + stepUv * (float(s) + jitter);
        if (!onScreen(uv)) break;
        vec4 q = viewPosition(uv);
        if (q.w < 0.5) continue;
        vec3 h = q.xyz - p.xyz;
        float dist = length(h);
        if (dist < 1e-4) continue;
        float falloff = clamp((radius - dist) / (kFalloffShare * radius), 0.0, 1.0);
        if (falloff <= 0.0) continue;  // out of range: neither an occluder nor a sign that one ended
        float e = dot(h / dist, n) * falloff;
        best = e > best ? e : mix(best, max(e, 0.0), kThicknessBlend);
    }
    return best;
}

void main()
{
    vec4 p = viewPosition(vUv);
    if (p.w < 0.5) { fragColour = kSkyAo; return; }
    vec3 n = viewNormal(vUv);
    vec3 v = normalize(-p.xyz);
    vec3 rnd = pixelNoise();
    vec2 radiusUv = 0.5 * projScale * radius / -p.z;
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
        vec2 stepUv = omega * radiusUv / float(steps);
        float h2 = gtaoHorizonFromElevation(highestElevation(p, n, stepUv, steps, jitter), angleN, npLength, 1.0);
        float h1 = gtaoHorizonFromElevation(highestElevation(p, n, -stepUv, steps, jitter), angleN, npLength, -1.0);
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
    float visibility = seen / max(open, 1e-4);
    float ao = pow(clamp(visibility, 1e-4, 1.0), visibilityPower);  // pow(0, 0) is undefined (intensity 0)
    if (multiBounce > 0.5) {
        vec3 albedo = pow(texelFetch(gbufferAlbedo, gbufferTexel(vUv), 0).rgb, vec3(2.2));
        ao = gtaoMultiBounce(ao, dot(albedo, vec3(0.2126, 0.7152, 0.0722)));
    }
    fragColour = aoResult(ao, -p.z);
}
