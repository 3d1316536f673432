#version 330 core
// The volumetrics' half-resolution buffer from this frame's quarter of its pixels (volumes.frag
// marched the pixel at volumeMarchPhase of each 2x2 block into volumeSample) and the buffer of the frame
// before (volumeHistory), in the spirit of Killzone Shadow Fall's interleaved volumetrics and of
// temporal anti-aliasing's history clamp (Karis 2014):
//   the pixel marched this frame   its new value, as is;
//   any other pixel                the frame before's buffer where this pixel's point was then
//                                  (reprojected through previousView at its surface's depth, or
//                                  far along the ray for the sky), clamped to the box (per channel
//                                  min / max) of the 3x3 new samples around it, so nothing the new
//                                  samples do not show survives: a view turned away, a disoccluded
//                                  wall, a cloud that appeared or went;
//   no history                     (the first frame of a chain, or reprojected off the buffer) the
//                                  new samples around it, upsampled depth-aware.
// Writes (in-scattered light, transmittance) as volumes.frag does; the output pass upsamples it.
uniform sampler2D volumeSample;    // this frame's march, FRAME_VOLUME_SAMPLE_SCALE
uniform sampler2D volumeHistory;   // the frame before's result, FRAME_VOLUME_SCALE
uniform sampler2D gbufferDepth;    // linear depth at full resolution (bound by the frame)
uniform vec2 volumeMarchPhase;          // the pixel of each 2x2 block marched this frame
uniform float volumeHistoryValid;  // 0 on a chain's first frame: volumeHistory holds nothing yet
uniform mat4 previousView;         // world -> the frame before's view space
in vec2 vUv;
out vec4 fragColour;
#include "frame_shared.h"
#include "view_ray.glsl"
const float kSkyReprojection = 1000.0;  // metres along the ray a sky pixel is reprojected at

float depthAt(ivec2 halfPixel, vec2 halfSize, ivec2 full)
{
    vec2 uv = (vec2(halfPixel) + 0.5) / halfSize;
    return texelFetch(gbufferDepth, clamp(ivec2(uv * vec2(full)), ivec2(0), full - 1), 0).r;
}

void main()
{
    ivec2 full = textureSize(gbufferDepth, 0), quarter = textureSize(volumeSample, 0);
    ivec2 halfSize = ivec2(vec2(full) * FRAME_VOLUME_SCALE);
    ivec2 pixel = min(ivec2(vUv * vec2(halfSize)), halfSize - 1);
    ivec2 phase = ivec2(volumeMarchPhase);
    ivec2 rel = pixel - phase;
    ivec2 below = ivec2(floor(vec2(rel) * 0.5));  // the sample at or before this pixel, each axis
    if (all(equal(rel, 2 * below)) && all(lessThan(below, quarter)) && all(greaterThanEqual(below, ivec2(0)))) {
        fragColour = texelFetch(volumeSample, below, 0);
        return;
    }
    // The 3x3 new samples around the nearest one: they include the 2x2 that bracket this pixel.
    ivec2 nearest = ivec2(floor(vec2(rel) * 0.5 + 0.5));
    // The last row or column of an odd-sized buffer lies past every phase's samples (OGRE rounds
    // the quarter buffer down): never marched, so never taken from a history it would keep.
    bool marchedSometime = all(lessThan(pixel, 2 * quarter));
    vec4 lo = vec4(1e30), hi = vec4(-1e30);
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            vec4 v = texelFetch(volumeSample, clamp(nearest + ivec2(x, y), ivec2(0), quarter - 1), 0);
            lo = min(lo, v);
            hi = max(hi, v);
        }
    float depth = depthAt(pixel, vec2(halfSize), full);
    vec3 viewPoint = viewRayAt((vec2(pixel) + 0.5) / vec2(halfSize)) * (depth > 0.0 ? depth : kSkyReprojection);
    vec3 before = (previousView * (inverseView * vec4(viewPoint, 1.0))).xyz;
    vec2 ndc = before.xy / max(-before.z, 1e-6) * projScale;
    vec2 uvBefore = ndc * 0.5 + 0.5;
    if (flipY > 0.5) uvBefore.y = 1.0 - uvBefore.y;
    if (marchedSometime && volumeHistoryValid > 0.5 && before.z < 0.0 && all(greaterThanEqual(uvBefore, vec2(0.0))) && all(lessThanEqual(uvBefore, vec2(1.0)))) {
        fragColour = clamp(texture(volumeHistory, uvBefore), lo, hi);
        return;
    }
    // No history: the bracketing new samples, by distance and by how near their depth is to this one.
    float z = depth > 0.0 ? depth : 1e4;
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            ivec2 s = clamp(below + ivec2(x, y), ivec2(0), quarter - 1);
            vec2 f = abs(vec2(phase + 2 * s - pixel)) * 0.5;  // 0 or 0.5 (1 past the edge) per axis
            float d = depthAt(phase + 2 * s, vec2(halfSize), full);
            float w = max(1.0 - f.x, 0.0) * max(1.0 - f.y, 0.0) * exp(-abs((d > 0.0 ? d : 1e4) - z) / z * FRAME_DEPTH_SHARPNESS) + 1e-4;
            sum += texelFetch(volumeSample, s, 0) * w;
            weights += w;
        }
    fragColour = sum / weights;
}
