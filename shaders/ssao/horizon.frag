#version 330 core
// Horizon-based AO (after Bavoil & Sainz, "Screen-space ambient occlusion", ShaderX7 / NVIDIA
// HBAO 2008): march a few screen-space directions (rotated per pixel) out to the projected radius;
// along each, the highest horizon above the tangent plane (the largest sine of elevation of
// H = sample - point against the normal) occludes, faded with distance. Finds large occluders that
// point samples skip, at the same sample count.
#include "ssao_common.glsl"
in vec2 vUv;
out vec4 fragColour;
const int kDirections = 4;  // x steps = the sample count (16 -> 4 steps a direction)
void main()
{
    vec4 p = viewPosition(vUv);
    if (p.w < 0.5) { fragColour = vec4(1.0); return; }
    vec3 n = viewNormal(vUv);
    vec3 rnd = pixelNoise();
    // The radius projected to texture space at this depth.
    vec2 radiusUv = 0.5 * projScale * radius / -p.z;
    int steps = max(int(sampleCount) / kDirections, 1);
    float angle0 = atan(rnd.y, rnd.x);
    float jitter = rnd.z * 0.5 + 0.5;
    float occ = 0.0;
    for (int d = 0; d < kDirections; ++d) {
        float a = angle0 + float(d) * (6.28318530718 / float(kDirections));
        vec2 dir = vec2(cos(a), sin(a));
        if (flipY > 0.5) dir.y = -dir.y;
        float best = 0.0;
        for (int s = 0; s < 8; ++s) {
            if (s >= steps) break;
            vec2 uv = vUv + dir * radiusUv * ((float(s) + jitter) / float(steps));
            if (uv.x < 0.0 || uv.x > 1.0 || uv.y < 0.0 || uv.y > 1.0) break;
            vec4 q = viewPosition(uv);
            if (q.w < 0.5) continue;
            vec3 h = q.xyz - p.xyz;
            float dist = length(h);
            if (dist < 1e-4) continue;
            // sin(elevation) above the tangent plane, less a small bias against flat-surface noise
            float elevation = dot(h / dist, n) - 0.1;
            float falloff = clamp(1.0 - (dist * dist) / (radius * radius), 0.0, 1.0);
            best = max(best, elevation * falloff);
        }
        occ += best;
    }
    float ao = 1.0 - intensity * occ / float(kDirections);
    fragColour = vec4(vec3(clamp(ao, 0.0, 1.0)), 1.0);
}
