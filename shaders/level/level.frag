#version 330 core
// Level surfaces into the frame's G-buffer (shaders/frame/frame_shared.h): the albedo, the normal,
// the depth and the direct light arriving here, as irradiance (linear, HDR):
//   the sun (worldspawn _sunlight), shadowed through a shadow map, wrapped a little so faces
//   turned away are not flat black
// + the map's light entities with Quake's falloff (map/quake_light.h has the same maths in C++, see
//   there for the formulas): every light whose reach meets this batch, LEVEL_MAX_LIGHTS at most
//   (LevelGeometry cuts chunks so no batch is reached by more).
// The hemispheric ambient (sky from above, ground from below), which AO darkens, is added by the
// frame's lighting pass (shaders/frame/lighting.frag), and the tone map is applied once at the end.
uniform sampler2D albedoMap;
uniform sampler2D sunShadowMap;  // -height/10^4 of the caster nearest the sun (shadow_caster.frag)
uniform vec4 sunShadowTexel;     // 1/width, 1/height, width, height of sunShadowMap
uniform vec3 sunDirection;    // world space, unit, pointing towards the sun
uniform vec3 sunColour;       // linear RGB
#include "level_shared.h"
uniform float lightCount;
// OGRE's per-light arrays, packed by LevelGeometry::buildLights:
uniform vec4 lightPositions[LEVEL_MAX_LIGHTS];    // world space; w = 0: the sun, lit apart with its shadow
uniform vec4 lightColours[LEVEL_MAX_LIGHTS];      // colour x value / 200: the irradiance at full strength
uniform vec4 lightAttenuations[LEVEL_MAX_LIGHTS]; // reach (m), formula (delay), map units per metre (x wait), gate / strength
uniform vec4 lightShapes[LEVEL_MAX_LIGHTS];       // _anglescale, _falloff_exponent, spotlight (1) or not (0)
uniform vec4 lightDirections[LEVEL_MAX_LIGHTS];   // spotlights: the way the light travels, world space
uniform vec4 spotParams[LEVEL_MAX_LIGHTS];        // spotlights: cos of half the soft cone, of half the cone

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
in vec4 vShadowPos;

#include "gbuffer_out.glsl"
// Materials without an albedo texture (the GBuffer scheme's shared fallback) count as light grey.
uniform float hasAlbedo;

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
    // 0.7 linear = 0.85 gamma-encoded: the light grey of untextured surfaces.
    vec3 albedo = hasAlbedo < 0.5 ? vec3(pow(0.7, 1.0 / 2.2)) : texture(albedoMap, vUv).rgb;

    vec3 light = vec3(0.0);
    float ndotl = dot(n, sunDirection);
    // Wrap lighting (0.2): keeps sunlit back faces from collapsing to the ambient floor.
    float sun = max((ndotl + 0.2) / 1.2, 0.0);
    if (sun > 0.0 && dot(sunColour, sunColour) > 0.0) sun *= sunVisibility(max(ndotl, 0.0));
    light += sunColour * sun;

    int count = int(lightCount);
    vec3 floorLight = vec3(0.0);  // delay 4 lights: a floor, not a sum
    for (int i = 0; i < LEVEL_MAX_LIGHTS; ++i) {
        if (i >= count) break;
        if (lightPositions[i].w == 0.0) continue;  // the sun: lit above, with its shadow
        vec4 att = lightAttenuations[i];
        vec3 toLight = lightPositions[i].xyz - vWorldPos;
        float dist = length(toLight);
        if (dist >= att.x) continue;  // beyond its reach
        int formula = int(att.y + 0.5);
        if (formula == LEVEL_LIGHT_LOCAL_MINIMUM) {
            floorLight = max(floorLight, lightColours[i].rgb);
            continue;
        }
        vec3 dir = toLight / max(dist, 1e-4);
        float cosine = dot(n, dir);
        if (cosine <= 0.0) continue;  // behind the surface
        vec4 shape = lightShapes[i];
        float strength;
        float x = dist * att.z;  // Quake's scaled distance, map units
        float xi = max(x, LEVEL_MIN_INVERSE_DISTANCE);
        if (formula == LEVEL_LIGHT_LINEAR) strength = pow(clamp(1.0 - dist / att.x, 0.0, 1.0), shape.y);
        else if (formula == LEVEL_LIGHT_INVERSE) strength = LEVEL_INVERSE_SCALE / xi;
        else if (formula == LEVEL_LIGHT_INVERSE_SQUARE) strength = LEVEL_INVERSE_SCALE * LEVEL_INVERSE_SCALE / (xi * xi);
        else if (formula == LEVEL_LIGHT_INVERSE_SQUARE_A) {
            float s = x + LEVEL_INVERSE_SCALE;
            strength = LEVEL_INVERSE_SCALE * LEVEL_INVERSE_SCALE / (s * s);
        } else strength = 1.0;
        strength = max(strength - att.w, 0.0);  // the inverse laws' gate (0 for the others)
        strength *= (1.0 - shape.x) + shape.x * cosine;
        if (shape.z > 0.5) {
            // The cone: 0 outside half its angle, a linear ramp in the cosine up to the soft cone.
            float c = dot(lightDirections[i].xyz, -dir);
            vec2 sp = spotParams[i].xy;
            strength *= sp.x > sp.y ? clamp((c - sp.y) / (sp.x - sp.y), 0.0, 1.0) : step(sp.y, c);
        }
        light += lightColours[i].rgb * strength;
    }
    light = max(max(light, vec3(0.0)), floorLight);  // negative lights subtract, down to 0

    writeGBuffer(albedo, light, vWorldPos, n);
}
