#version 330 core
// Crytek-style SSAO (Mittring, "Finding next gen: CryEngine 2", SIGGRAPH 2007 course; seed a):
// depth-only: samples in a sphere around the point, reflected by a per-pixel random vector,
// counted as occluded when the visible surface at the sample's pixel lies in front of it.
// A flat wall occludes half a sphere, so only the occlusion above one half darkens.
#include "ssao_common.glsl"
in vec2 vUv;
out vec4 fragColour;
void main()
{
    vec4 p = viewPosition(vUv);
    if (p.w < 0.5) { fragColour = kSkyAo; return; }
    vec3 rnd = pixelNoise();
    int n = int(sampleCount);
    float occ = 0.0;
    for (int i = 0; i < SSAO_MAX_SAMPLES; ++i) {
        if (i >= n) break;
        vec3 s = reflect(kernel[i], rnd) * radius;
        occ += occluderAt(p.xyz + s, p.z);
    }
    float ao = 1.0 - intensity * max(occ / float(n) - 0.5, 0.0) * 2.0;
    fragColour = aoResult(ao, -p.z);
}
