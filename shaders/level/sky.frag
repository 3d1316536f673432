#version 330 core
// Sky brushes: unlit, a vertical gradient from the horizon colour to the zenith colour.
uniform vec3 skyZenith;    // gamma-encoded RGB
uniform vec3 skyHorizon;   // gamma-encoded RGB
uniform vec3 cameraPosition;

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

out vec4 fragColour;

void main()
{
    vec3 dir = normalize(vWorldPos - cameraPosition);
    float t = clamp(dir.y * 1.5, 0.0, 1.0);
    fragColour = vec4(mix(skyHorizon, skyZenith, sqrt(t)), 1.0);
}
