#version 330 core
// Level surfaces: world-space position and normal for per-pixel lighting. See level.frag.
uniform mat4 worldViewProj;
uniform mat4 world;

in vec4 vertex;
in vec3 normal;
in vec2 uv0;

out vec3 vWorldPos;
out vec3 vNormal;
out vec2 vUv;

void main()
{
    vWorldPos = (world * vertex).xyz;
    vNormal = mat3(world) * normal;
    vUv = uv0;
    gl_Position = worldViewProj * vertex;
}
