#version 330 core
// Billboards of the combat effects (muzzle flash, impact sparks): OGRE's BillboardSet gives
// camera-facing quads with a colour and texture coordinates.
uniform mat4 worldViewProj;
in vec4 vertex;
in vec4 colour;
in vec2 uv0;
out vec4 vColour;
out vec2 vUv;
void main()
{
    gl_Position = worldViewProj * vertex;
    vColour = colour;
    vUv = uv0;
}
