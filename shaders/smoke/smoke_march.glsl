// Ray-marching the smoke grenades' volumes (engine_ext/smoke) in the frame's volumetrics stage,
// against the G-buffer's linear depth: each view ray is marched from the volume's entry (or the
// camera, when inside it) to its exit or the first opaque surface, whichever is nearer, so walls and
// props hide the smoke behind them. Per step: the density from the 3D texture (R, times the
// export scale) with sub-grid value noise so the 25 cm grid never shows, Beer-Lambert extinction,
// and in-scattered light = sky/ground ambient + the sun times the volume's own transmittance
// towards it (G: self-shadowing). The start is jittered per pixel against banding.
// Needs: inverseView, projScale, flipY, vUv; ObscuraLighting's sun and ambient.
#include "smoke_shared.h"
uniform float smokeCount;          // volumes bound (0..SMOKE_MAX_VOLUMES)
uniform vec3 smokeMin[SMOKE_MAX_VOLUMES];      // world AABB of each volume's grid (its texture)
uniform vec3 smokeSize[SMOKE_MAX_VOLUMES];
uniform vec3 smokeBoxMin[SMOKE_MAX_VOLUMES];   // the part of it holding smoke: only this is marched
uniform vec3 smokeBoxSize[SMOKE_MAX_VOLUMES];
uniform sampler3D smokeMap0;
uniform sampler3D smokeMap1;
uniform sampler3D smokeMap2;
uniform sampler3D smokeMap3;
uniform float smokeDensityScale;   // the solver's exportDensityScale: texture 1.0 = this density
uniform float smokeTime;           // seconds of game time: the noise drifts
uniform vec3 sunDirection;
uniform vec3 sunColour;
uniform vec3 skyAmbient;
uniform vec3 groundAmbient;
const float kSmokeSigma = 6.0;     // extinction per metre at density 1: 1 m of thick smoke passes 0.25 %
const vec3 kSmokeAlbedo = vec3(0.82, 0.82, 0.8);  // light grey, a little warm
const float kSmokeStep = 0.25;     // metres: the grid's cell size; finer shows no more detail
const int kSmokeMaxSteps = 64;     // a 16 m crossing
// A rotation (orthonormal) for the noise lattice: value noise is blocky along its lattice axes;
// turned off the world axes it cannot line up with the grid's cells or with a view down a
// corridor. (The blocky look smoke had in roofed corridors was the sun's light, which reached
// it through the roof: the solver's transmittance now counts walls and roofs.)
const mat3 kNoiseTurn = mat3(0.00, 0.80, 0.60, -0.80, 0.36, -0.48, -0.60, -0.48, 0.64);

vec2 smokeSample(int i, vec3 uvw)
{
    if (i == 0) return texture(smokeMap0, uvw).rg;
    if (i == 1) return texture(smokeMap1, uvw).rg;
    if (i == 2) return texture(smokeMap2, uvw).rg;
    return texture(smokeMap3, uvw).rg;
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

// Marches every volume along origin + t * dir for t < maxT; light (HDR, exposed) and transmittance
// accumulate front to back within a volume (volumes are taken in binding order).
void marchSmoke(vec3 origin, vec3 dir, float maxT, float jitter, inout vec3 light, inout float transmittance)
{
    vec3 ambient = mix(groundAmbient, skyAmbient, 0.65);  // a cloud sees mostly sky
    int count = int(smokeCount);
    for (int i = 0; i < SMOKE_MAX_VOLUMES; ++i) {
        if (i >= count) break;
        vec3 lo = smokeBoxMin[i], hi = smokeBoxMin[i] + smokeBoxSize[i];
        vec3 inv = 1.0 / (dir + vec3(equal(dir, vec3(0.0))) * 1e-6);
        vec3 ta = (lo - origin) * inv, tb = (hi - origin) * inv;
        float t0 = max(max(min(ta.x, tb.x), min(ta.y, tb.y)), max(min(ta.z, tb.z), 0.0));
        float t1 = min(min(max(ta.x, tb.x), max(ta.y, tb.y)), min(max(ta.z, tb.z), maxT));
        if (t1 <= t0) continue;
        int steps = clamp(int(ceil((t1 - t0) / kSmokeStep)), 1, kSmokeMaxSteps);
        float dt = (t1 - t0) / float(steps);
        for (int s = 0; s < kSmokeMaxSteps; ++s) {
            if (s >= steps) break;
            vec3 p = origin + dir * (t0 + (float(s) + jitter) * dt);
            vec2 st = smokeSample(i, (p - smokeMin[i]) / smokeSize[i]);
            if (st.r <= 0.0) continue;
            // Sub-grid detail: two octaves at 1.3 and 2.9 cycles a metre, drifting upwards, on
            // lattices turned off the world axes.
            vec3 q = kNoiseTurn * (p + vec3(0.0, -0.3 * smokeTime, 0.0));
            float detail = 0.55 + 0.6 * smokeNoise(q * 1.3) + 0.3 * (smokeNoise(kNoiseTurn * q * 2.9) - 0.5);
            float density = st.r * smokeDensityScale * detail;
            float stepT = exp(-kSmokeSigma * density * dt);
            vec3 lit = kSmokeAlbedo * (ambient + sunColour * st.g);
            light += transmittance * (1.0 - stepT) * lit;
            transmittance *= stepT;
            if (transmittance < 0.003) return;
        }
    }
}
