#version 330 core
// G-buffer for the AO modes: view-space position and normal of every opaque surface, and the
// world normal and UV for its ambient term.
uniform mat4 worldViewProj;
uniform mat4 worldView;
uniform mat4 world;
in vec4 vertex;
in vec3 normal;
in vec2 uv0;
out vec3 vViewPos;
out vec3 vViewNormal;
out vec3 vWorldNormal;
out vec2 vUv;
void main()
{
    vViewPos = (worldView * vertex).xyz;
    vViewNormal = mat3(worldView) * normal;
    vWorldNormal = mat3(world) * normal;
    vUv = uv0;
    gl_Position = worldViewProj * vertex;
}
