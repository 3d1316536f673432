#version 330 core
// Sun shadow map: renders casters from the sun; see shadow_caster.frag.
uniform mat4 worldViewProj;
uniform mat4 world;
uniform vec3 sunDirection;  // world space, towards the sun (the same value as level.frag's)
in vec4 vertex;
in vec2 uv0;
out float vHeight;
out vec2 vUv;  // for fence casters' alpha test (shadow_caster.frag)
void main()
{
    gl_Position = worldViewProj * vertex;
    vUv = uv0;
    vHeight = dot((world * vertex).xyz, sunDirection);
}
