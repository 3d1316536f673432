#version 330 core
// A sign's shadow map (engine_ext/signs): the distance from the lamp to the nearest surface, metres
// (sign_light.glsl's signShadowAt compares a point's own distance with it; 0 = nothing there).
uniform vec3 lampPosition;  // world, set before each sign's map is drawn
in vec3 vWorldPos;
out vec4 fragColour;
void main()
{
    fragColour = vec4(length(vWorldPos - lampPosition), 0.0, 0.0, 1.0);
}
