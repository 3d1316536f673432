#version 330 core
// Simple, cheap level lighting (the AO modes of later issues modulate the ambient term):
//   hemispheric ambient (sky colour from above, ground colour from below)
// + an unshadowed sun (worldspawn _sunlight), wrapped a little so faces turned away are not flat black
// + up to 8 point lights per batch with Quake-like falloff reaching zero at the light's range.
// Albedo is stored gamma-encoded; lighting is done in linear space and tone-mapped at the end.
uniform sampler2D albedoMap;
uniform vec3 skyAmbient;      // linear RGB, light arriving from above
uniform vec3 groundAmbient;   // linear RGB, light bounced from below
uniform vec3 sunDirection;    // world space, unit, pointing towards the sun
uniform vec3 sunColour;       // linear RGB
uniform float exposure;       // multiplies the lit colour before tone mapping
uniform float lightCount;
uniform vec4 lightPositions[8];    // world space (OGRE light_position_array)
uniform vec4 lightColours[8];      // OGRE light_diffuse_colour_array
uniform vec4 lightAttenuations[8]; // x = range (OGRE light_attenuation_array)

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

out vec4 fragColour;

void main()
{
    vec3 n = normalize(vNormal);
    vec3 albedo = pow(texture(albedoMap, vUv).rgb, vec3(2.2));

    vec3 light = mix(groundAmbient, skyAmbient, 0.5 + 0.5 * n.y);
    // Wrap lighting (0.2): keeps unshadowed back faces from collapsing to the ambient floor.
    light += sunColour * max((dot(n, sunDirection) + 0.2) / 1.2, 0.0);

    int count = int(lightCount);
    for (int i = 0; i < 8; ++i) {
        if (i >= count) break;
        vec3 toLight = lightPositions[i].xyz - vWorldPos;
        float dist = length(toLight);
        float range = max(lightAttenuations[i].x, 1e-3);
        float falloff = clamp(1.0 - dist / range, 0.0, 1.0);
        float ndotl = max(dot(n, toLight / max(dist, 1e-4)), 0.0);
        light += lightColours[i].rgb * (falloff * falloff * ndotl);
    }

    vec3 colour = albedo * light * exposure;
    colour = vec3(1.0) - exp(-colour);   // exponential tone map: never clips hard
    fragColour = vec4(pow(colour, vec3(1.0 / 2.2)), 1.0);
}
