#version 330 core
// Level surfaces: world-space position and normal for per-pixel lighting, the position in the
// sun's shadow map (OGRE texture shadows, texture 0) and the lightmap's uv (uv1: the level's baked
// faces only, engine_ext/lightbake; other meshes have none and level.frag does not read it). See level.frag.
uniform mat4 worldViewProj;
uniform mat4 world;
uniform mat4 sunShadowViewProj;  // world -> shadow map (xy in [0,1], z in clip units)

in vec4 vertex;
in vec3 normal;
in vec2 uv0;
in vec2 uv1;

out vec3 vWorldPos;
out vec3 vNormal;
out vec2 vUv;
out vec4 vShadowPos;
out vec2 vLightmapUv;

void main()
{
    vec4 worldPos = world * vertex;
    vWorldPos = worldPos.xyz;
    vNormal = mat3(world) * normal;
    vUv = uv0;
    vLightmapUv = uv1;
    vShadowPos = sunShadowViewProj * worldPos;
    gl_Position = worldViewProj * vertex;
}
