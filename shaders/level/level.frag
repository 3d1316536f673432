#version 330 core
// Simple, cheap level lighting (the AO modes of later issues modulate the ambient term):
//   hemispheric ambient (sky colour from above, ground colour from below)
// + the sun (worldspawn _sunlight), shadowed through a shadow map, wrapped a little so faces
//   turned away are not flat black
// + up to 8 point lights per batch with Quake-like falloff reaching zero at the light's range.
// Albedo is stored gamma-encoded; lighting is done in linear space and tone-mapped at the end.
// Compiled twice (media/materials/level.program): as is for the plain view, and with
// OBSCURA_GBUFFER for the AO modes' G-buffer scheme, where the same lighting is written untone-mapped
// beside linear depth, view normal and the ambient term (shaders/ssao/README in engine_ext/ssao).
uniform sampler2D albedoMap;
uniform sampler2D sunShadowMap;  // -height/10^4 of the caster nearest the sun (shadow_caster.frag)
uniform vec4 sunShadowTexel;     // 1/width, 1/height, width, height of sunShadowMap
uniform vec3 skyAmbient;      // linear RGB, light arriving from above
uniform vec3 groundAmbient;   // linear RGB, light bounced from below
uniform vec3 sunDirection;    // world space, unit, pointing towards the sun
uniform vec3 sunColour;       // linear RGB
uniform float exposure;       // multiplies the lit colour before tone mapping
uniform float lightCount;
uniform vec4 lightPositions[8];    // world space (OGRE light_position_array); w = 0: the sun, skipped
uniform vec4 lightColours[8];      // OGRE light_diffuse_colour_array
uniform vec4 lightAttenuations[8]; // x = range (OGRE light_attenuation_array)

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
in vec4 vShadowPos;

#ifdef OBSCURA_GBUFFER
#include "gbuffer_out.glsl"
// Materials without an albedo texture (the AO scheme's shared fallback) count as light grey.
uniform float hasAlbedo;
#else
out vec4 fragColour;
#endif

// Fraction of the sun reaching this point: 2x2 percentage-closer filtering of the shadow map.
float sunVisibility(float ndotl)
{
    vec2 p = vShadowPos.xy / vShadowPos.w;
    if (p.x <= 0.0 || p.x >= 1.0 || p.y <= 0.0 || p.y >= 1.0) return 1.0;  // outside the map: lit
    // Slope-scaled bias, metres: 3 cm facing the sun, up to 15 cm at grazing angles (acne-free
    // on 1024^2 texels spread over up to 50 m).
    float height = dot(vWorldPos, sunDirection) + 0.03 + 0.12 * (1.0 - ndotl);
    float receiver = -height * 1e-4;
    float lit = 0.0;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            vec2 uv = p + (vec2(x, y) - 0.5) * sunShadowTexel.xy;
            lit += (receiver <= texture(sunShadowMap, uv).r) ? 1.0 : 0.0;
        }
    return lit * 0.25;
}

void main()
{
    vec3 n = normalize(vNormal);
    vec3 albedo = pow(texture(albedoMap, vUv).rgb, vec3(2.2));
#ifdef OBSCURA_GBUFFER
    if (hasAlbedo < 0.5) albedo = vec3(0.7);
#endif

    vec3 ambient = mix(groundAmbient, skyAmbient, 0.5 + 0.5 * n.y);
    vec3 light = ambient;
    float ndotl = dot(n, sunDirection);
    // Wrap lighting (0.2): keeps sunlit back faces from collapsing to the ambient floor.
    float sun = max((ndotl + 0.2) / 1.2, 0.0);
    if (sun > 0.0 && dot(sunColour, sunColour) > 0.0) sun *= sunVisibility(max(ndotl, 0.0));
    light += sunColour * sun;

    int count = int(lightCount);
    for (int i = 0; i < 8; ++i) {
        if (i >= count) break;
        if (lightPositions[i].w == 0.0) continue;  // the sun: lit above, with its shadow
        vec3 toLight = lightPositions[i].xyz - vWorldPos;
        float dist = length(toLight);
        float range = max(lightAttenuations[i].x, 1e-3);
        float falloff = clamp(1.0 - dist / range, 0.0, 1.0);
        float ndotp = max(dot(n, toLight / max(dist, 1e-4)), 0.0);
        light += lightColours[i].rgb * (falloff * falloff * ndotp);
    }

    vec3 colour = albedo * light * exposure;
#ifdef OBSCURA_GBUFFER
    writeGBuffer(colour, albedo * ambient * exposure, vWorldPos, n);
#else
    colour = vec3(1.0) - exp(-colour);   // exponential tone map: never clips hard
    fragColour = vec4(pow(colour, vec3(1.0 / 2.2)), 1.0);
#endif
}
