#version 330 core
// Level surfaces into the frame's G-buffer (shaders/frame/frame_shared.h): the albedo, the normal,
// the depth and the direct light arriving here, as irradiance (linear, HDR):
//   the sun (worldspawn _sunlight), shadowed through a shadow map, wrapped a little so faces
//   turned away are not flat black
// + up to 8 point lights per batch with Quake-like falloff reaching zero at the light's range.
// The hemispheric ambient (sky from above, ground from below), which AO darkens, is added by the
// frame's lighting pass (shaders/frame/lighting.frag), and the tone map is applied once at the end.
uniform sampler2D albedoMap;
uniform sampler2D sunShadowMap;  // -height/10^4 of the caster nearest the sun (shadow_caster.frag)
uniform vec4 sunShadowTexel;     // 1/width, 1/height, width, height of sunShadowMap
uniform vec3 sunDirection;    // world space, unit, pointing towards the sun
uniform vec3 sunColour;       // linear RGB
uniform float lightCount;
uniform vec4 lightPositions[8];    // world space (OGRE light_position_array); w = 0: the sun, skipped
uniform vec4 lightColours[8];      // OGRE light_diffuse_colour_array
uniform vec4 lightAttenuations[8]; // x = range (OGRE light_attenuation_array)

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
in vec4 vShadowPos;

#include "gbuffer_out.glsl"
#include "sun_wrap.glsl"
// Materials without an albedo texture (the GBuffer scheme's shared fallback) count as light grey.
uniform float hasAlbedo;
// Fence textures (`{` names): texels with alpha below this are holes (0.5); 0 = opaque surfaces.
uniform float alphaCutoff;

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
    vec4 texel = hasAlbedo < 0.5 ? vec4(vec3(pow(0.7, 1.0 / 2.2)), 1.0) : texture(albedoMap, vUv);
    if (texel.a < alphaCutoff) discard;  // a hole: no G-buffer write, so AO and the view see through
    vec3 albedo = texel.rgb;

    vec3 light = vec3(0.0);
    float ndotl = dot(n, sunDirection);
    float sun = sunWrap(ndotl);
    float visible = sun > 0.0 ? 1.0 : 0.0;
    if (sun > 0.0 && dot(sunColour, sunColour) > 0.0) visible = sunVisibility(max(ndotl, 0.0));
    light += sunColour * (sun * visible);

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

    writeGBuffer(albedo, light, visible, vWorldPos, n);
}
