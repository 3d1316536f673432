#version 330 core
// The ambient term is the same as level.frag's (albedo x hemispheric sky/ground light x exposure,
// before tone mapping), so the modulate pass can take AO off it alone.
uniform sampler2D albedoMap;
uniform float hasAlbedo;
uniform vec3 skyAmbient;
uniform vec3 groundAmbient;
uniform float exposure;
in vec3 vViewPos;
in vec3 vViewNormal;
in vec3 vWorldNormal;
in vec2 vUv;
layout(location = 0) out vec4 outPosition;  // view space, metres; w = 1 where there is geometry
layout(location = 1) out vec4 outNormal;    // view space, unit
layout(location = 2) out vec4 outAmbient;   // linear HDR ambient contribution
void main()
{
    outPosition = vec4(vViewPos, 1.0);
    outNormal = vec4(normalize(vViewNormal), 1.0);
    vec3 albedo = hasAlbedo > 0.5 ? pow(texture(albedoMap, vUv).rgb, vec3(2.2)) : vec3(1.0);
    vec3 n = normalize(vWorldNormal);
    outAmbient = vec4(albedo * mix(groundAmbient, skyAmbient, 0.5 + 0.5 * n.y) * exposure, 1.0);
}
