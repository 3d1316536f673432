// The smoke grenades' volumes (engine_ext/smoke) in the frame's volumetric pass
// (shaders/frame/volumes.frag), which marches each view ray through the volumes' occupied boxes
// (smokeSegments), up to the first opaque surface, so walls and props hide the smoke behind them.
// Per sample (smokeAt): the density from the 3D texture (R, HDR float) with
// sub-grid value noise so the 25 cm grid never shows, Beer-Lambert extinction at the solver's own
// shadowSigma (the march and the self-shadowing agree), and the light scattered towards the eye:
//   sun    sunColour x the solver's transmittance towards the sun (G) through a Henyey-Greenstein
//          phase (g = 0.3, forward), plus two weaker, wider "octaves" of multiple scattering
//          (Wrenninge et al. 2013: transmittance^0.5 and ^0.25, weights 0.5 and 0.25, g halved
//          each time), so the lit side is bright, the core and the far side a shaded grey; all of
//          it x the level's sun shadow map at the sample (smokeSunShadow): the solver's
//          transmittance holds the smoke and the walls and roofs inside its box, the map every
//          caster of the level, the tall building outside the box too (engine_ext/smoke/README.md,
//          "Rendering and play", says why the product counts a wall in the box once)
//   sky    the baked indirect light where the cloud is (engine_ext/lightbake's irradiance volume:
//          the sky where the sky is seen, the level's bounce; black in a sealed room), read once
//          a ray, x the smoke's own occlusion: how open the cell is upwards through the smoke
//          above it (B, swept by the solver), never below kSmokeIndirect (the light scattered in
//          from the sides and many times over), so a dense core is darker than its rim
//   lamps  the level's point lights near the smoke (engine_ext/smoke/smoke_lamps.cpp picks at most
//          SMOKE_MAX_LIGHTS), with the surfaces' falloff (1 - d / range)^2, the brightest
//          x the smoke's and its walls' transmittance towards them (the lamp maps), summed on the
//          grid by the smoke's worker (smoke_lamp_light.h: two texels a cell in smokeLampLight, the
//          light and its lamps' mean direction) and read here with one phase about that
//          direction (smokeLampLightAt): two taps a sample, not a loop over the lamps.
// Phases are scaled by pi: light arriving as the surfaces' irradiance E makes a white Lambertian
// surface send E back; the same light makes smoke send (albedo x pi x phase x E) per unit of
// opacity: isotropic scattering 0.25 E.
// Needs: ObscuraLighting's sun; ObscuraBakedLight and lightProbes; VOLUME_MAX_SEGMENTS (volumes.frag).
#include "smoke_shared.h"
#include "volume_phase.glsl"
#include "sun_shadow.glsl"  // sunShadowMap, sunShadowTexel (bound by smoke_render.cpp)
uniform mat4 sunShadowViewProj;    // world -> sunShadowMap (xy in [0, 1] after the divide), as level.vert's
uniform float smokeCount;          // volumes bound (0..SMOKE_MAX_VOLUMES)
uniform vec3 smokeMin[SMOKE_MAX_VOLUMES];      // world AABB of each volume's grid (its texture)
uniform vec3 smokeSize[SMOKE_MAX_VOLUMES];
uniform vec3 smokeBoxMin[SMOKE_MAX_VOLUMES];   // the part of it holding smoke: only this is marched
uniform vec3 smokeBoxSize[SMOKE_MAX_VOLUMES];
uniform sampler3D smokeMap0;       // PF_FLOAT32_RGB: density, transmittance to the sun, sky visibility
uniform sampler3D smokeMap1;
uniform sampler3D smokeMap2;
uniform sampler3D smokeMap3;
uniform sampler3D smokeLampMap0;   // PF_FLOAT32_RGBA: transmittance towards shadowed lamp c in channel c
uniform sampler3D smokeLampMap1;
uniform sampler3D smokeLampMap2;
uniform sampler3D smokeLampMap3;
uniform float smokeShadowedCount;  // lamp map channels in use (0..4): the level's lamps', then the signs'
uniform vec3 smokeShadowedPosition[4];  // world position of each channel's lamp
uniform sampler3D smokeLampLight;  // PF_FLOAT32_RGBA atlas: volume i's A at slab 2i, B at 2i + 1 (smoke_lamp_light.h)
uniform float smokeLampLightCells; // the grid's cells a side (the slabs' depth)
uniform float smokeSigma;          // extinction per metre per density unit (SmokeSettings::shadowSigma)
uniform float smokeTime;           // seconds of game time: the noise drifts
uniform float smokeLightCount;     // lamps lighting the smoke (0..SMOKE_MAX_LIGHTS): 0, no light to read
uniform vec3 sunDirection;
uniform vec3 sunColour;
#include "baked_ambient.glsl"   // lightProbes, probeAmbient
const vec3 kSmokeAlbedo = vec3(0.9, 0.9, 0.88);  // single-scattering albedo: light grey, a little warm
const float kSmokeG = 0.3;         // Henyey-Greenstein asymmetry: smoke scatters somewhat forwards
// Metres towards the sun a sample is moved before the shadow map's test: a volume has no slope
// to scale by; 0.2 m is level.frag's grazing bias (0.15 m) with a margin, so a sample in the air
// just in front of a sunlit wall is not shadowed by the wall's own texels, and under the grid's
// 0.25 m cell, so what leaks past a caster is no more than the solver's transmittance resolves.
const float kSmokeShadowBias = 0.2;
const float kSmokeIndirect = 0.3;  // the ambient's share that reaches smoke the smoke above hides from
                                   // the sky (scattered in from the sides and many times over)
// The baked ambient at the first sample of a ray that has smoke (probes 1 m or more apart: one read a
// ray, not two 3D taps a sample); `smokeAmbientRead` false until then.
vec3 smokeAmbient;
bool smokeAmbientRead = false;
// A rotation (orthonormal) for the noise lattice: value noise is blocky along its lattice axes;
// turned off the world axes it cannot line up with the grid's cells or with a view down a
// corridor. (The blocky look smoke had in roofed corridors was the sun's light, which reached
// it through the roof: the solver's transmittance now counts walls and roofs.)
const mat3 kNoiseTurn = mat3(0.00, 0.80, 0.60, -0.80, 0.36, -0.48, -0.60, -0.48, 0.64);

vec3 smokeSample(int i, vec3 uvw)
{
    if (i == 0) return texture(smokeMap0, uvw).rgb;
    if (i == 1) return texture(smokeMap1, uvw).rgb;
    if (i == 2) return texture(smokeMap2, uvw).rgb;
    return texture(smokeMap3, uvw).rgb;
}

vec4 smokeLampSample(int i, vec3 uvw)
{
    if (i == 0) return texture(smokeLampMap0, uvw);
    if (i == 1) return texture(smokeLampMap1, uvw);
    if (i == 2) return texture(smokeLampMap2, uvw);
    return texture(smokeLampMap3, uvw);
}

// The lamps' light scattered along -dir at uvw of volume i (smoke_lamp_light.h): A's light
// through the phase about B's mean direction, the asymmetry scaled by B's length; the single share
// (A.a) at g, the rest (the multiple-scattering octave) at g / 2, as the sun's.
vec3 smokeLampLightAt(int i, vec3 uvw, vec3 dir)
{
    // Each slab's outer half-texel is clamped off, so no tap blends two slabs.
    float cells = smokeLampLightCells, slabs = float(2 * SMOKE_MAX_VOLUMES);
    float w = clamp(uvw.z, 0.5 / cells, 1.0 - 0.5 / cells);
    vec4 light = texture(smokeLampLight, vec3(uvw.xy, (float(2 * i) + w) / slabs));
    vec3 mean = texture(smokeLampLight, vec3(uvw.xy, (float(2 * i + 1) + w) / slabs)).xyz;
    float k = length(mean);
    float c = k > 1e-4 ? dot(dir, mean) / k : 0.0;
    return light.rgb * (light.a * volumePhase(c, kSmokeG * k) + (1.0 - light.a) * volumePhase(c, 0.5 * kSmokeG * k));
}

// The transmittance from p towards each shadowed lamp (channel c: smokeShadowedPosition[c]),
// the product over the volumes: what the signs' light passes (volumes.frag). Inside a volume's grid its lamp map at p; outside it, the map where
// the segment from p to the lamp enters the grid (what the map holds there is the rest of that
// segment inside the grid); a segment that misses the grid passes whole.
vec4 smokeLampTransmittance(vec3 p)
{
    vec4 T = vec4(1.0);
    int count = int(smokeCount), lamps = int(smokeShadowedCount);
    if (lamps == 0) return T;
    for (int i = 0; i < SMOKE_MAX_VOLUMES; ++i) {
        if (i >= count) break;
        vec3 lo = smokeMin[i], size = smokeSize[i];
        vec3 uvw = (p - lo) / size;
        if (all(greaterThanEqual(uvw, vec3(0.0))) && all(lessThanEqual(uvw, vec3(1.0)))) {
            T *= smokeLampSample(i, uvw);
            continue;
        }
        for (int l = 0; l < 4; ++l) {
            if (l >= lamps) break;
            vec3 d = smokeShadowedPosition[l] - p;
            vec3 inv = 1.0 / (d + vec3(equal(d, vec3(0.0))) * 1e-6);
            vec3 ta = (lo - p) * inv, tb = (lo + size - p) * inv;
            float t0 = max(max(min(ta.x, tb.x), min(ta.y, tb.y)), max(min(ta.z, tb.z), 0.0));
            float t1 = min(min(max(ta.x, tb.x), max(ta.y, tb.y)), min(max(ta.z, tb.z), 1.0));
            if (t1 > t0) T[l] *= smokeLampSample(i, (p + d * t0 - lo) / size)[l];
        }
    }
    return T;
}

float smokeHash(vec3 p)
{
    p = fract(p * 0.3183099 + 0.1);
    p *= 17.0;
    return fract(p.x * p.y * p.z * (p.x + p.y + p.z));
}

// Value noise, trilinear between hashed lattice values: 0..1.
float smokeNoise(vec3 p)
{
    vec3 i = floor(p), f = fract(p);
    f = f * f * (3.0 - 2.0 * f);
    return mix(mix(mix(smokeHash(i), smokeHash(i + vec3(1, 0, 0)), f.x),
                   mix(smokeHash(i + vec3(0, 1, 0)), smokeHash(i + vec3(1, 1, 0)), f.x), f.y),
               mix(mix(smokeHash(i + vec3(0, 0, 1)), smokeHash(i + vec3(1, 0, 1)), f.x),
                   mix(smokeHash(i + vec3(0, 1, 1)), smokeHash(i + vec3(1, 1, 1)), f.x), f.y), f.z);
}


// The level's sun shadow map at p: 0 behind a caster, 1 in the sun (and outside the map, and
// without a sun: nothing to shadow, nothing read).
float smokeSunShadow(vec3 p)
{
    if (dot(sunColour, sunColour) <= 0.0) return 1.0;
    vec4 s = sunShadowViewProj * vec4(p, 1.0);
    return sunShadowLit(s.xy / s.w, dot(p, sunDirection) + kSmokeShadowBias);
}

// The smoke's parts of a view ray origin + t * dir, t < maxT: each volume's occupied box as an
// interval, added to the volumetric pass's list (shaders/frame/volumes.frag marches them merged).
void smokeSegments(vec3 origin, vec3 dir, float maxT, inout int n, inout float segT0[VOLUME_MAX_SEGMENTS],
                   inout float segT1[VOLUME_MAX_SEGMENTS])
{
    int count = int(smokeCount);
    vec3 inv = 1.0 / (dir + vec3(equal(dir, vec3(0.0))) * 1e-6);
    for (int i = 0; i < SMOKE_MAX_VOLUMES; ++i) {
        if (i >= count) break;
        vec3 lo = smokeBoxMin[i], hi = smokeBoxMin[i] + smokeBoxSize[i];
        vec3 ta = (lo - origin) * inv, tb = (hi - origin) * inv;
        float t0 = max(max(min(ta.x, tb.x), min(ta.y, tb.y)), max(min(ta.z, tb.z), 0.0));
        float t1 = min(min(max(ta.x, tb.x), max(ta.y, tb.y)), min(max(ta.z, tb.z), maxT));
        if (t1 <= t0) continue;
        segT0[n] = t0;
        segT1[n] = t1;
        ++n;
    }
}

// The smoke at p seen along dir: rgb = the light it scatters towards the eye per unit of its
// extinction (albedo x sun, sky and lamps through the phase), a = its extinction (per metre).
// Where volumes overlap, their light is averaged by extinction (one volume: its own, exactly).
vec4 smokeAt(vec3 p, vec3 dir)
{
    // Light travels along -sunDirection; the eye looks along dir: scattering angle cos = dir . sun.
    float cosSun = dot(dir, sunDirection);
    vec3 sunPhase = vec3(volumePhase(cosSun, kSmokeG), 0.7 * volumePhase(cosSun, 0.5 * kSmokeG),
                         0.5 * volumePhase(cosSun, 0.25 * kSmokeG));
    int count = int(smokeCount);
    bool lights = smokeLightCount > 0.5;
    vec3 scattered = vec3(0.0);
    float sigma = 0.0;
    float sunShadow = -1.0;  // the shadow map at p: read once, at the first volume with smoke here
    for (int i = 0; i < SMOKE_MAX_VOLUMES; ++i) {
        if (i >= count) break;
        vec3 lo = smokeBoxMin[i], hi = lo + smokeBoxSize[i];
        if (any(lessThan(p, lo)) || any(greaterThan(p, hi))) continue;
        vec3 uvw = (p - smokeMin[i]) / smokeSize[i];
        vec3 cell = smokeSample(i, uvw);
        // Float densities are never quite 0 where the smoke has been: below 0.004 (what the
        // 8-bit texture rounded to 0; the marched box's threshold, smoke_render.cpp) a step
        // passes 99.6 %, and the noise and lights are skipped.
        if (cell.r < 0.004) continue;
        // Sub-grid detail: two octaves at 1.3 and 2.9 cycles a metre, drifting upwards, on
        // lattices turned off the world axes.
        vec3 q = kNoiseTurn * (p + vec3(0.0, -0.3 * smokeTime, 0.0));
        float detail = 0.55 + 0.6 * smokeNoise(q * 1.3) + 0.3 * (smokeNoise(kNoiseTurn * q * 2.9) - 0.5);
        float s = smokeSigma * cell.r * detail;
        float sunT = clamp(cell.g, 0.0, 1.0), sunT2 = sqrt(sunT);
        if (sunShadow < 0.0) sunShadow = smokeSunShadow(p);
        if (!smokeAmbientRead) {
            smokeAmbient = probeAmbient(p, vec3(0.0, 0.3, 0.0));  // 0.65 of the way to the up side: a cloud sees mostly sky
            smokeAmbientRead = true;
        }
        vec3 lit = sunColour * (sunShadow * dot(sunPhase, vec3(sunT, sunT2, sqrt(sunT2))))
                 + smokeAmbient * mix(kSmokeIndirect, 1.0, clamp(cell.b, 0.0, 1.0));
        if (lights) lit += smokeLampLightAt(i, uvw, dir);
        lit *= kSmokeAlbedo;
        if (sigma == 0.0) scattered = lit;
        else scattered = (scattered * sigma + lit * s) / (sigma + s);
        sigma += s;
    }
    return vec4(scattered, sigma);
}
