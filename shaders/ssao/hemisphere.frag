#version 330 core
// Normal-oriented hemisphere SSAO (gamerendering.com, after Crysis/StarCraft II; seed a): the
// energy-minimised hemisphere kernel (engine_ext/ssao/ssao_kernel.h) is rotated about the surface
// normal by a per-pixel random vector (Gram-Schmidt frame), so no sample lies behind the surface.
#include "ssao_common.glsl"
in vec2 vUv;
out vec4 fragColour;
void main()
{
    vec4 p = viewPosition(vUv);
    if (p.w < 0.5) { fragColour = kSkyAo; return; }
    vec3 n = viewNormal(vUv);
    vec3 rnd = pixelNoise();
    vec3 t = normalize(rnd - n * dot(rnd, n));
    mat3 tbn = mat3(t, cross(n, t), n);
    int count = int(sampleCount);
    float occ = 0.0;
    for (int i = 0; i < SSAO_MAX_SAMPLES; ++i) {
        if (i >= count) break;
        occ += occluderAt(p.xyz + tbn * kernel[i] * radius, p.z);
    }
    float ao = 1.0 - intensity * occ / float(count);
    fragColour = aoResult(ao, -p.z);
}
