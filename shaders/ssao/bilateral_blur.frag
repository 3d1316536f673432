#version 330 core
// Depth-aware (cross-bilateral) blur of the AO term: a 5-tap line along `direction` (separable:
// run horizontally, then vertically), each tap weighted down by its relative depth difference from
// the centre so occlusion does not bleed across silhouettes. Runs at the AO's resolution on the
// (AO, depth) pairs the AO pass wrote, and passes the centre's depth on for the upsampling.
#include "frame_shared.h"
uniform sampler2D blurSource;  // r = AO, g = linear depth (0 = sky)
uniform vec2 direction;        // (1, 0) or (0, 1): one texel along x or y
in vec2 vUv;
out vec4 fragColour;
void main()
{
    ivec2 last = textureSize(blurSource, 0) - 1;
    ivec2 pixel = clamp(ivec2(vUv * vec2(last + 1)), ivec2(0), last);
    vec2 centre = texelFetch(blurSource, pixel, 0).rg;
    if (centre.g <= 0.0) { fragColour = vec4(1.0, 0.0, 0.0, 1.0); return; }
    float sum = 0.0, weights = 0.0;
    for (int i = -2; i <= 2; ++i) {
        vec2 tap = texelFetch(blurSource, clamp(pixel + i * ivec2(direction), ivec2(0), last), 0).rg;
        float w = exp(-abs(tap.g - centre.g) / centre.g * FRAME_DEPTH_SHARPNESS) * (3.0 - abs(float(i)));
        sum += tap.r * w;
        weights += w;
    }
    fragColour = vec4(sum / max(weights, 1e-5), centre.g, 0.0, 1.0);
}
