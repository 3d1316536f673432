#version 330 core
// Ground-truth-based AO (Jimenez, Wu, Pesce, Jarabo, "Practical Real-Time Strategies for Accurate
// Indirect Occlusion", SIGGRAPH 2016): the cosine-weighted visibility of the hemisphere, integrated
// per slice: the search is gtao_search.glsl (shared with the combined mode's small scale), the slice
// math gtao.glsl (mirrored by engine_ext/ssao/gtao.h).
in vec2 vUv;
out vec4 fragColour;
#include "ssao_common.glsl"
#include "gtao.glsl"
#include "gtao_search.glsl"
uniform sampler2D gbufferAlbedo;  // gamma albedo (the frame's G-buffer), for the multi-bounce fit
uniform float visibilityPower;    // intensity / its default (ssao_compositor.cpp): 1 = the visibility itself
uniform float multiBounce;        // 1: the multi-bounce fit with this pixel's albedo (media/ssao/ssao.program says why it is off)
void main()
{
    vec4 p = viewPosition(vUv);
    if (p.w < 0.5) { fragColour = kSkyAo; return; }
    vec3 n = viewNormal(vUv);
    vec3 rnd = pixelNoise();
    float visibility = gtaoVisibilityWithin(p, n, rnd, radius);
    float ao = pow(clamp(visibility, 1e-4, 1.0), visibilityPower);  // pow(0, 0) is undefined (intensity 0)
    if (multiBounce > 0.5) {
        vec3 albedo = pow(texelFetch(gbufferAlbedo, gbufferTexel(vUv), 0).rgb, vec3(2.2));
        ao = gtaoMultiBounce(ao, dot(albedo, vec3(0.2126, 0.7152, 0.0722)));
    }
    fragColour = aoResult(ao, -p.z);
}
