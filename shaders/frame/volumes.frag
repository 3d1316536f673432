#version 330 core
// The frame's volumetric pass, a quarter of the half-resolution pixels a frame (the one of each 2x2
// block at volumeMarchPhase; shaders/frame/volume_resolve.frag fills the rest): every participating medium marched together
// along each view ray against the G-buffer's linear depth, with ONE transmittance, so a medium in
// front dims what lies behind it and nothing is counted twice:
//   smoke  the grenades' volumes (engine_ext/smoke, shaders/smoke/smoke_march.glsl): absorbs and
//          scatters the sun, the sky, the level's lamps and the signs' light, and shadows the
//          brightest lamps and the signs' lamps (its lamp maps, smokeLampTransmittance);
//   haze   a thin scatterer of the signs' light (engine_ext/signs, shaders/signs/sign_march.glsl).
// The ray's pieces inside any smoke box or sign beam are merged into disjoint segments, marched
// front to back with a per-pixel jittered start. Per step of length dt, with extinction s (smoke) and
// source J (light scattered towards the eye per metre), the step adds T J (1 - e^(-s dt)) / s (the
// integral of the step's source through its own extinction: Hillaire 2015, energy-conserving) and T
// becomes T e^(-s dt). Writes the in-scattered light (linear HDR) and the transmittance; the output
// pass upsamples them depth-aware and lays them over the light.
uniform sampler2D gbufferDepth;  // linear depth at full resolution (bound by the frame)
uniform vec2 volumeMarchPhase;       // the half-resolution pixel of each 2x2 block marched this frame (Frame)
in vec2 vUv;
out vec4 fragColour;
#define VOLUME_MAX_SEGMENTS 6  // SMOKE_MAX_VOLUMES boxes + SIGN_MAX_LIGHTS beams
#include "frame_shared.h"
#include "view_ray.glsl"
#include "smoke_march.glsl"
#include "sign_march.glsl"
const float kVolumeStep = 0.25;  // metres: the smoke grid's cell (finer shows no more of it) and
                                 // a third of a sign's letter at the default size
const int kVolumeMaxSteps = 64;  // per segment: a 16 m crossing

void main()
{
    vec3 light = vec3(0.0);
    float transmittance = 1.0;
    // This texel's half-resolution pixel and its centre (the buffers' sizes as OGRE truncates them).
    ivec2 size = textureSize(gbufferDepth, 0);
    ivec2 halfSize = ivec2(vec2(size) * FRAME_VOLUME_SCALE);
    ivec2 pixel = min(2 * ivec2(vUv * vec2(ivec2(vec2(size) * FRAME_VOLUME_SAMPLE_SCALE))) + ivec2(volumeMarchPhase), halfSize - 1);
    vec2 uv = (vec2(pixel) + 0.5) / vec2(halfSize);
    float depth = texelFetch(gbufferDepth, clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1), 0).r;
    vec3 viewDir = normalize(viewRayAt(uv));
    float maxT = depth > 0.0 ? depth / -viewDir.z : 1e4;
    vec3 origin = inverseView[3].xyz, dir = normalize(mat3(inverseView) * viewDir);

    float segT0[VOLUME_MAX_SEGMENTS], segT1[VOLUME_MAX_SEGMENTS];
    int n = 0;
    smokeSegments(origin, dir, maxT, n, segT0, segT1);
    signSegments(origin, dir, maxT, n, segT0, segT1);
    // Front to back (insertion sort of at most 6), overlapping pieces merged.
    for (int i = 1; i < VOLUME_MAX_SEGMENTS; ++i) {
        if (i >= n) break;
        for (int j = i; j > 0 && segT0[j] < segT0[j - 1]; --j) {
            float a = segT0[j]; segT0[j] = segT0[j - 1]; segT0[j - 1] = a;
            float b = segT1[j]; segT1[j] = segT1[j - 1]; segT1[j - 1] = b;
        }
    }
    int merged = 0;
    for (int i = 0; i < VOLUME_MAX_SEGMENTS; ++i) {
        if (i >= n) break;
        if (merged > 0 && segT0[i] <= segT1[merged - 1]) {
            segT1[merged - 1] = max(segT1[merged - 1], segT1[i]);
        } else {
            segT0[merged] = segT0[i];
            segT1[merged] = segT1[i];
            ++merged;
        }
    }
    // Interleaved gradient noise (Jimenez 2014) of the half-resolution pixel: the start jitter,
    // stable from frame to frame (a still view converges to one image).
    float jitter = fract(52.9829189 * fract(dot(vec2(pixel) + 0.5, vec2(0.06711056, 0.00583715))));
    bool signs = signCount > 0.5;
    // Each bound sign's channel in the smoke's lamp maps, matched by its lamp's position (the
    // signs and the smoke pick their lamps apart); -1: not shadowed.
    int signChannel[SIGN_MAX_LIGHTS];
    bool signShadowed = false;  // a sign's lamp has a channel: the lamp maps are read a sample
    for (int i = 0; i < SIGN_MAX_LIGHTS; ++i) {
        signChannel[i] = -1;
        for (int c = 0; c < 4; ++c)
            if (float(c) < smokeShadowedCount && distance(smokeShadowedPosition[c], signLamp[i].xyz) < 1e-3) signChannel[i] = c;
        signShadowed = signShadowed || (signs && float(i) < signCount && signChannel[i] >= 0);
    }
    for (int g = 0; g < VOLUME_MAX_SEGMENTS; ++g) {
        if (g >= merged || transmittance < 0.003) break;
        float t0 = segT0[g], t1 = segT1[g];
        int steps = clamp(int(ceil((t1 - t0) / kVolumeStep)), 1, kVolumeMaxSteps);
        float dt = (t1 - t0) / float(steps);
        for (int s = 0; s < kVolumeMaxSteps; ++s) {
            if (s >= steps) break;
            vec3 p = origin + dir * (t0 + (float(s) + jitter) * dt);
            vec4 lampT = signShadowed ? smokeLampTransmittance(p) : vec4(1.0);
            vec4 smoke = smokeAt(p, dir);
            float signShadow[SIGN_MAX_LIGHTS];
            for (int i = 0; i < SIGN_MAX_LIGHTS; ++i) signShadow[i] = signChannel[i] >= 0 ? lampT[signChannel[i]] : 1.0;
            vec3 signLight = signs ? signScatterAt(p, dir, signShadow) : vec3(0.0);
            float stepT = exp(-smoke.a * dt);
            // (1 - e^(-s dt)) / s, which is dt where the smoke is too thin to dim its own step.
            float through = smoke.a * dt > 1e-4 ? (1.0 - stepT) / smoke.a : dt;
            light += transmittance * ((1.0 - stepT) * smoke.rgb + through * (smoke.a * kSmokeAlbedo + signHaze) * signLight);
            transmittance *= stepT;
            if (transmittance < 0.003) break;
        }
    }
    fragColour = vec4(light, transmittance);
}
