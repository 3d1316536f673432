#version 330 core
// The heightfield mode's top-down height map (ssao_compositor.cpp renders it once per level with an
// orthographic camera looking down): every surface writes its world height.
uniform mat4 worldViewProj;
uniform mat4 world;
in vec4 vertex;
out float vHeight;
void main()
{
    vHeight = (world * vertex).y;
    gl_Position = worldViewProj * vertex;
}
