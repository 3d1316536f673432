// Depth-aware upsampling of the frame's lower-resolution buffers to a full-resolution pixel
// (joint bilateral upsampling, Kopf et al. 2007): the four texels around the pixel with their
// bilinear weights times how close their depth is to the pixel's, so nothing bleeds across a
// silhouette. Needs frame_shared.h.

float bilinearWeight(int x, int y, vec2 f) { return (x == 0 ? 1.0 - f.x : f.x) * (y == 0 ? 1.0 - f.y : f.y); }

// AO buffers hold (AO, the depth it was computed at). `depth` > 0.
float upsampledAo(sampler2D aoMap, vec2 uv, float depth)
{
    // One bilinear tap gives the AO and the depth of the four texels averaged: where that depth
    // matches this pixel's (no silhouette among them, most of the frame) it is the answer.
    vec2 blended = texture(aoMap, uv).rg;
    if (abs(blended.g - depth) < FRAME_SAME_SURFACE * depth) return blended.r;
    vec2 size = vec2(textureSize(aoMap, 0));
    vec2 st = uv * size - 0.5;
    vec2 base = floor(st), f = st - base;
    float sum = 0.0, weights = 0.0;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            vec2 tap = texelFetch(aoMap, clamp(ivec2(base) + ivec2(x, y), ivec2(0), ivec2(size) - 1), 0).rg;
            float w = bilinearWeight(x, y, f) * exp(-abs(tap.g - depth) / max(depth, 1e-3) * FRAME_DEPTH_SHARPNESS) + 1e-4;
            sum += tap.r * w;
            weights += w;
        }
    return sum / weights;
}

// Volume buffers hold (in-scattered light, transmittance), marched against the full-resolution
// depth at each texel's centre. Sky (depth 0) counts as very far.
vec4 upsampledVolume(sampler2D volumeMap, sampler2D depthMap, vec2 uv, float depth)
{
    vec4 blended = texture(volumeMap, uv);
    if (blended.a >= 0.999) return blended;  // clear air around this pixel
    vec2 size = vec2(textureSize(volumeMap, 0));
    vec2 st = uv * size - 0.5;
    vec2 base = floor(st), f = st - base;
    ivec2 full = textureSize(depthMap, 0);
    float z = depth > 0.0 ? depth : 1e4;
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            ivec2 texel = clamp(ivec2(base) + ivec2(x, y), ivec2(0), ivec2(size) - 1);
            vec2 centre = (vec2(texel) + 0.5) / size;
            float d = texelFetch(depthMap, clamp(ivec2(centre * vec2(full)), ivec2(0), full - 1), 0).r;
            float w = bilinearWeight(x, y, f) * exp(-abs((d > 0.0 ? d : 1e4) - z) / z * FRAME_DEPTH_SHARPNESS) + 1e-4;
            sum += texelFetch(volumeMap, texel, 0) * w;
            weights += w;
        }
    return sum / weights;
}
