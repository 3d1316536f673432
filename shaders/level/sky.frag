#version 330 core
// Sky brushes: unlit, a vertical gradient from the horizon colour to the zenith colour (as shown).
uniform vec3 skyZenith;    // gamma-encoded RGB
uniform vec3 skyHorizon;   // gamma-encoded RGB
uniform vec3 cameraPosition;

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

#include "gbuffer_out.glsl"

void main()
{
    vec3 dir = normalize(vWorldPos - cameraPosition);
    float t = clamp(dir.y * 1.5, 0.0, 1.0);
    vec3 sky = mix(skyHorizon, skyZenith, sqrt(t));
    // Depth 0 marks "nothing here": no ambient to occlude, no surface for AO or volumes to stop at.
    // The albedo slot holds the colour as shown (the lighting pass undoes the tone map for it).
    writeGBuffer(sky, vec3(0.0), 0.0, vec3(0.0), cameraPosition + dir * 1e6, -dir);
    outDepth = vec4(0.0);
}
