#version 330 core
// G-buffer for the AO modes: view-space position and normal of every opaque surface.
uniform mat4 worldViewProj;
uniform mat4 worldView;
in vec4 vertex;
in vec3 normal;
out vec3 vViewPos;
out vec3 vViewNormal;
void main()
{
    vViewPos = (worldView * vertex).xyz;
    vViewNormal = mat3(worldView) * normal;
    gl_Position = worldViewProj * vertex;
}
