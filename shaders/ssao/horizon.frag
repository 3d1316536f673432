#version 330 core
// The horizon mode: HBAO (horizon.glsl) alone.
in vec2 vUv;
out vec4 fragColour;
#include "ssao_common.glsl"
#include "horizon.glsl"
void main()
{
    vec4 p = viewPosition(vUv);
    if (p.w < 0.5) { fragColour = kSkyAo; return; }
    fragColour = aoResult(1.0 - horizonOcclusion(p, viewNormal(vUv), pixelNoise()), -p.z);
}
