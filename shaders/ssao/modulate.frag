#version 330 core
// Applies AO to the ambient light only: the lit scene is un-tone-mapped (level.frag's
// 1 - exp(-x) after gamma 2.2), the occluded share of the ambient term is taken off, and the result
// tone-mapped again. Direct sun and point light stay as they were. Or shows the AO alone.
uniform sampler2D sceneMap;
uniform sampler2D aoMap;
uniform sampler2D ambientMap;
uniform float aoOnly;
in vec2 vUv;
out vec4 fragColour;
void main()
{
    float ao = texture(aoMap, vUv).r;
    if (aoOnly > 0.5) { fragColour = vec4(vec3(ao), 1.0); return; }
    vec3 mapped = pow(texture(sceneMap, vUv).rgb, vec3(2.2));
    vec3 hdr = -log(max(vec3(1.0) - mapped, vec3(1.0 / 1024.0)));
    hdr = max(hdr - texture(ambientMap, vUv).rgb * (1.0 - ao), vec3(0.0));
    fragColour = vec4(pow(vec3(1.0) - exp(-hdr), vec3(1.0 / 2.2)), 1.0);
}
