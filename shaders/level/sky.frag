#version 330 core
// Sky brushes: unlit, a vertical gradient from the horizon colour to the zenith colour.
uniform vec3 skyZenith;    // gamma-encoded RGB
uniform vec3 skyHorizon;   // gamma-encoded RGB
uniform vec3 cameraPosition;

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

#ifdef OBSCURA_GBUFFER
#include "gbuffer_out.glsl"
#else
out vec4 fragColour;
#endif

void main()
{
    vec3 dir = normalize(vWorldPos - cameraPosition);
    float t = clamp(dir.y * 1.5, 0.0, 1.0);
    vec3 sky = mix(skyHorizon, skyZenith, sqrt(t));
#ifdef OBSCURA_GBUFFER
    // Depth 0 marks "nothing here" for the AO passes; no ambient to occlude.
    writeGBuffer(vec3(0.0), vec3(0.0), cameraPosition + dir * 1e6, -dir);
    outColour = vec4(sky, 1.0);
    outDepth = vec4(0.0);
#else
    fragColour = vec4(sky, 1.0);
#endif
}
