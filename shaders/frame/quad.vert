#version 330 core
// Full-screen quad for the frame's and the techniques' passes.
uniform mat4 worldViewProj;
in vec4 vertex;
in vec2 uv0;
out vec2 vUv;
void main()
{
    gl_Position = worldViewProj * vertex;
    vUv = uv0;
}
