#version 330 core
// A decal's box (engine_ext/decals/decal_render.cpp): uv0.x is its slot in the data texture.
uniform mat4 worldViewProj;
uniform mat4 worldView;
in vec4 vertex;
in vec2 uv0;
out vec3 vViewPos;
flat out int vSlot;
void main()
{
    gl_Position = worldViewProj * vertex;
    vViewPos = (worldView * vertex).xyz;
    vSlot = int(uv0.x + 0.5);
}
