#version 330 core
// Cone-test SSAO (malmer.nu, "Screen-space ambient occlusion", 2008; seed b): camera-space
// positions are rebuilt from depth; each sample of the relaxed sphere kernel is projected to the
// screen, and the surface found there occludes only if it lies inside a cone around the normal
// (150 degrees wide, so grazing neighbours on the same plane never count) and within the radius.
#include "ssao_common.glsl"
in vec2 vUv;
out vec4 fragColour;
const float kConeCos = 0.2588;  // cos(75 degrees): the cone's half-angle
void main()
{
    vec4 p = viewPosition(vUv);
    if (p.w < 0.5) { fragColour = kSkyAo; return; }
    vec3 n = viewNormal(vUv);
    vec3 rnd = pixelNoise();
    int count = int(sampleCount);
    float occ = 0.0;
    for (int i = 0; i < SSAO_MAX_SAMPLES; ++i) {
        if (i >= count) break;
        vec3 q = p.xyz + reflect(kernel[i], rnd) * radius;
        vec2 uv = projectToUv(q);
        if (!onScreen(uv)) continue;  // off the screen: unknown, not an occluder
        vec4 s = viewPosition(uv);
        if (s.w < 0.5) continue;
        vec3 v = s.xyz - p.xyz;
        float dist = length(v);
        if (dist < 1e-4 || dist > radius) continue;
        occ += dot(v / dist, n) > kConeCos ? 1.0 - dist / radius : 0.0;
    }
    float ao = 1.0 - intensity * occ / float(count);
    fragColour = aoResult(ao, -p.z);
}
