// GTAO's horizon search (Jimenez, Wu, Pesce, Jarabo 2016), shared by the gtao mode and the combined
// mode's small scale: kGtaoSlices screen-space directions (the per-pixel random vector, turned by
// 180/kGtaoSlices degrees each: no trigonometry for the directions), each the plane through V and
// that direction; along it the horizon is searched both ways out to the reach projected at the
// pixel's depth (sampleCount steps in all), the normal is projected into the slice, and the
// visibility between the two horizons is the paper's analytic inner integral (gtao.glsl).
// Needs ssao_common.glsl and gtao.glsl.
// 2 slices x 2 sides. Steps a side: the samples knob's share (8 at the default 32, the horizon
// mode's 4 directions x 8 steps) where the reach projects to few texels, more near the camera (one
// per kStepTexels, up to 4x). Steps a side are what the error follows (room_a, 0.6 m truth,
// 1280x720 scored at 320x180: 4 steps a side .100 occluded-region MAE, 8 steps .070; Sibenik's nave
// 8 / 16 / 32 steps everywhere .077 / .068 / .063: too light where 8 steps across a hundred
// texels step over a moulding's crease; 1 slice x 8 steps, the same 16 samples, .107: noisier;
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

// The stride, in depth texels along the slice, that sets the steps a side near the camera
// (gtaoVisibilities): a reach of 96 texels or more gets the 4x cap (at 0.6 m, 1280x720 and a 90
// degree field of view, a surface within 4 m). Chosen on Sibenik's nave and pillars and room_b
// (0.6 m truth, occluded-region MAE; 8 steps everywhere .078 / .080 / .087): a stride of
// 2.1 / 2.5 / 2.8 / 3 / 3.5 / 4.2 texels gave .063 at each in the nave (at the cap), pillars
// .066 / .066 / .066 / .066 / .067 / .068, room_b .073 / .075 / .078 / .078 / .083 / .084. 3 keeps
// the pillars inside issue 14's 3x goal (.068) with the courtyard's cost (the timedemo's) near
// 8 steps': the far courtyard stays at 8.
const float kStepTexels = 3.0;

// A horizon sample at texel-space position `at`: (the sine of its elevation above the tangent plane,
// its distance); distance 0 where there is nothing to see (sky, or the pixel's own texel). In the
// depth texture's texels (texelFrame: a multiply-add to view space, one inversesqrt for the
// distance and the direction), so a step costs a fetch and a dozen flops.
vec2 elevationAt(TexelFrame f, vec4 p, vec3 n, vec2 at)
{
    vec4 q = viewPositionAtTexel(f, min(ivec2(at), f.size - 1));
    vec3 h = q.xyz - p.xyz;
    float d2 = dot(h, h);
    if (q.w < 0.5 || d2 < 1e-8) return vec2(0.0);
    float invDist = inversesqrt(d2);
    return vec2(dot(h, n) * invDist, d2 * invDist);
}

// Keeps the higher elevation in `best`, the sample faded to the rim near `reach` (kFalloffShare).
// Out of range it is neither an occluder nor a sign that one ended.
void keepHighest(inout float best, vec2 hit, float reach)
{
    float falloff = clamp((reach - hit.y) / (kFalloffShare * reach), 0.0, 1.0);
    if (falloff <= 0.0) return;
    float e = hit.x * falloff;
    best = e > best ? e : mix(best, max(e, 0.0), kThicknessBlend);
}

// The highest elevations on one side, marched from the pixel along the screen direction `side`
// (uv per metre of reach at this depth): x within `reach` (`steps` samples), y within `farReach`
// (the same samples, then `farSteps` more between the two reaches; farSteps 0: y is x). 0 is the
// hemisphere's rim. An elevation, not the angle from V, so a plane never occludes itself
// (engine_ext/ssao/gtao.h, horizonFromElevation, says why). Past the screen's border nothing is
// known: the march stops there.
vec2 highestElevations(TexelFrame f, vec4 p, vec3 n, vec2 side, float jitter, float reach, int steps, float farReach, int farSteps)
{
    vec2 size = vec2(f.size);
    vec2 start = vUv * size;
    vec2 perMetre = side * size;
    vec2 best = vec2(0.0);
    for (int s = 0; s < SSAO_MAX_SAMPLES; ++s) {
        if (s >= steps) break;
        vec2 at = start + perMetre * (reach * (float(s) + jitter) / float(steps));
        if (!onScreenTexels(at, size)) return best;
        vec2 hit = elevationAt(f, p, n, at);
        if (hit.y <= 0.0) continue;
        keepHighest(best.x, hit, reach);
        keepHighest(best.y, hit, farReach);
    }
    for (int s = 0; s < SSAO_MAX_SAMPLES; ++s) {
        if (s >= farSteps) break;
        vec2 at = start + perMetre * mix(reach, farReach, (float(s) + jitter) / float(farSteps));
        if (!onScreenTexels(at, size)) break;
        vec2 hit = elevationAt(f, p, n, at);
        if (hit.y > 0.0) keepHighest(best.y, hit, farReach);
    }
    return farSteps > 0 ? best : best.xx;
}

// The cosine-weighted visibilities (1 = open) of view-space point p with normal n: x by what lies
// within `reach` metres of it (the radius), y within `farReach` (combined.frag's large radius under
// a roof; equal to reach: y is x and costs nothing), from one march a side.
vec2 gtaoVisibilities(vec4 p, vec3 n, vec3 rnd, float reach, float farReach)
{
    vec3 v = normalize(-p.xyz);
    vec2 perMetreUv = 0.5 * projScale / -p.z;
    TexelFrame f = texelFrame();
    // Steps a side: the samples knob's share (8 at the default 32), more where the reach covers many
    // texels, one per kStepTexels up to 4x (SSAO_MAX_SAMPLES): near surfaces, whose creases fall
    // between 8 steps across a hundred texels, get the steps; far ones, where 8 steps already fall
    // on every other texel, pay nothing (see kStepTexels). The far leg keeps the knob's share.
    int knobSteps = max(int(sampleCount) / (2 * kGtaoSlices), 1);
    float reachTexels = perMetreUv.x * reach * float(f.size.x);  // along any direction: square texels
    int steps = clamp(int(reachTexels / kStepTexels), knobSteps, min(4 * knobSteps, SSAO_MAX_SAMPLES));
    int farSteps = farReach > reach ? knobSteps : 0;
    float jitter = rnd.z * 0.5 + 0.5;
    vec2 omega = normalize(rnd.xy + vec2(1e-4, 0.0));  // the slice's direction on the screen (uv)
    vec2 seen = vec2(0.0);
    float open = 0.0;
    for (int i = 0; i < kGtaoSlices; ++i) {
        // The same direction in view space (uv's y runs down when render textures are flipped).
        vec3 d = vec3(omega.x, flipY > 0.5 ? -omega.y : omega.y, 0.0);
        vec3 ortho = d - dot(d, v) * v;              // the slice's axis beside V
        vec3 axis = normalize(cross(ortho, v));      // the slice plane's normal
        vec3 np = n - axis * dot(n, axis);           // the normal projected into the slice
        float npLength = length(np);
        float cosN = clamp(dot(np, v) / max(npLength, 1e-4), -1.0, 1.0);
        float angleN = (dot(ortho, np) < 0.0 ? -1.0 : 1.0) * acos(cosN);
        vec2 side = omega * perMetreUv;
        vec2 e2 = highestElevations(f, p, n, side, jitter, reach, steps, farReach, farSteps);
        vec2 e1 = highestElevations(f, p, n, -side, jitter, reach, steps, farReach, farSteps);
        for (int k = 0; k < 2; ++k) {
            float h2 = gtaoHorizonFromElevation(e2[k], angleN, npLength, 1.0);
            float h1 = gtaoHorizonFromElevation(e1[k], angleN, npLength, -1.0);
            seen[k] += npLength * gtaoSliceIntegral(h1, h2, angleN);
        }
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

// Within `reach` alone (the gtao mode).
float gtaoVisibilityWithin(vec4 p, vec3 n, vec3 rnd, float reach) { return gtaoVisibilities(p, n, rnd, reach, reach).x; }
