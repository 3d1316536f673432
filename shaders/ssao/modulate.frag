#version 330 core
// Applies the AO term to the lit scene (or shows it alone: the AO-only view).
uniform sampler2D sceneMap;
uniform sampler2D aoMap;
uniform float aoOnly;
in vec2 vUv;
out vec4 fragColour;
void main()
{
    float ao = texture(aoMap, vUv).r;
    vec3 scene = texture(sceneMap, vUv).rgb;
    fragColour = vec4(aoOnly > 0.5 ? vec3(ao) : scene * ao, 1.0);
}
