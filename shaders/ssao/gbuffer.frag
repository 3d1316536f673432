#version 330 core
// The G-buffer, kept small for llvmpipe's bandwidth: linear depth (32-bit float; view positions
// are rebuilt from it and the pixel), the normal packed in 8 bits a channel, and the ambient term
// (albedo x hemispheric sky/ground light x exposure, as level.frag computes it before tone
// mapping) so the modulate pass can take AO off it alone.
uniform sampler2D albedoMap;
uniform float hasAlbedo;
uniform vec3 skyAmbient;
uniform vec3 groundAmbient;
uniform float exposure;
in vec3 vViewPos;
in vec3 vViewNormal;
in vec3 vWorldNormal;
in vec2 vUv;
layout(location = 0) out vec4 outDepth;    // metres in front of the camera; 0 = nothing (sky)
layout(location = 1) out vec4 outNormal;   // view space, packed to 0..1
layout(location = 2) out vec4 outAmbient;  // linear HDR ambient contribution
void main()
{
    outDepth = vec4(-vViewPos.z, 0.0, 0.0, 1.0);
    outNormal = vec4(normalize(vViewNormal) * 0.5 + 0.5, 1.0);
    vec3 albedo = hasAlbedo > 0.5 ? pow(texture(albedoMap, vUv).rgb, vec3(2.2)) : vec3(1.0);
    vec3 n = normalize(vWorldNormal);
    outAmbient = vec4(albedo * mix(groundAmbient, skyAmbient, 0.5 + 0.5 * n.y) * exposure, 1.0);
}
