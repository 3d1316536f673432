#version 330 core
// Sun shadow map: renders casters from the sun; see shadow_caster.frag.
uniform mat4 worldViewProj;
uniform mat4 world;
uniform vec3 sunDirection;  // world space, towards the sun (the same value as level.frag's)
in vec4 vertex;
out float vHeight;
void main()
{
    gl_Position = worldViewProj * vertex;
    vHeight = dot((world * vertex).xyz, sunDirection);
}
