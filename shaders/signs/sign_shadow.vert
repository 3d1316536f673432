#version 330 core
// A sign's shadow map (engine_ext/signs): the world position of every surface seen from the lamp.
uniform mat4 worldViewProj;
uniform mat4 world;
in vec4 vertex;
out vec3 vWorldPos;
void main()
{
    vWorldPos = (world * vertex).xyz;
    gl_Position = worldViewProj * vertex;
}
