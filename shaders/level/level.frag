#version 330 core
// Level surfaces into the frame's G-buffer (shaders/frame/frame_shared.h): the albedo, the normal,
// the depth, the direct light and the ambient arriving here, as irradiance (linear, HDR):
//   the sun (worldspawn _sunlight), shadowed through a shadow map, wrapped a little so faces
//   turned away are not flat black;
// a baked face (`baked`: the level's static faces, engine_ext/lightbake):
// + the map's light entities with their shadows, from the lightmap (lightmapDirect.rgb), and the
//   sun's shadow map times the bake's sun visibility (.a), so no seam of the map lets sun into a
//   room the sun cannot reach
//   ambient: the lightmap's indirect light (sky seen, one bounce; lightmapIndirect)
// anything else (props, models, movers: no lightmap):
// + the map's light entities with Quake's falloff (map/quake_light.h has the same maths in C++, see
//   there for the formulas), unshadowed: every light listed for this point's grid cell
//   ambient: the irradiance volume (baked_ambient.glsl)
// AO darkens the ambient in the frame's lighting pass (shaders/frame/lighting.frag), and the tone
// map is applied once at the end.
uniform sampler2D albedoMap;
#include "sun_shadow.glsl"  // sunShadowMap, sunShadowTexel
uniform vec3 sunDirection;    // world space, unit, pointing towards the sun
uniform vec3 sunColour;       // linear RGB
#include "level_shared.h"
// The map's lights and the lights of each cell of a world grid (engine_ext/render/light_grid.h has
// the layout), set per level by LevelGeometry (shared_params ObscuraLevelLights, level.program).
uniform sampler2D levelLights;
uniform vec4 lightGridOrigin;  // xyz: the grid's low corner (m); w: the cell edge (m)
uniform vec4 lightGridSize;    // cells along x, y, z; w: the texture's width in texels
uniform vec4 lightGridBases;   // x: the cells' first texel, y: the light numbers' first texel
#include "baked_ambient.glsl"   // lightProbes, probeAmbient
uniform float baked;            // 1: a level face with a lightmap chart (LevelMaterials::resolveBaked)
uniform sampler2D lightmapDirect;    // RGBA16F: the lights' irradiance with shadows; a = the sun's visibility
uniform sampler2D lightmapIndirect;  // RGBA16F: the indirect irradiance

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
in vec4 vShadowPos;
in vec2 vLightmapUv;

#include "gbuffer_out.glsl"
#include "sun_share.glsl"
// Materials without an albedo texture (the GBuffer scheme's shared fallback) count as light grey.
uniform float hasAlbedo;
// Fence textures (`{` names): texels with alpha below this are holes (0.5); 0 = opaque surfaces.
uniform float alphaCutoff;

// Integer division is scalar on llvmpipe (no SIMD divide): the width is a power of two, so shifts.
ivec2 texel(int address, int width) { return ivec2(address & (LEVEL_LIGHT_ROW - 1), address >> LEVEL_LIGHT_ROW_LOG2); }

// Fraction of the sun reaching this point: 2x2 percentage-closer filtering of the shadow map.
float sunVisibility(float ndotl)
{
    // Slope-scaled bias, metres: 3 cm facing the sun, up to 15 cm at grazing angles (acne-free
    // on 1024^2 texels spread over up to 50 m).
    return sunShadowLit(vShadowPos.xy / vShadowPos.w, dot(vWorldPos, sunDirection) + 0.03 + 0.12 * (1.0 - ndotl));
}

// The map's lights reaching this point's grid cell, unshadowed (surfaces without a lightmap).
vec3 gridLights(vec3 n, vec3 light)
{
    vec3 floorLight = vec3(0.0);  // delay 4 lights: a floor, not a sum
    ivec3 cell = ivec3(floor((vWorldPos - lightGridOrigin.xyz) / lightGridOrigin.w));
    ivec3 cells = ivec3(lightGridSize.xyz);
    if (all(greaterThanEqual(cell, ivec3(0))) && all(lessThan(cell, cells))) {
        int width = int(lightGridSize.w);
        vec4 header = texelFetch(levelLights, texel(int(lightGridBases.x) + cell.x + cells.x * (cell.y + cells.y * cell.z), width), 0);
        int first = int(lightGridBases.y) + int(header.x);
        int count = int(header.y);
        for (int k = 0; k < count; ++k) {
            int base = LEVEL_LIGHT_TEXELS * int(texelFetch(levelLights, texel(first + k, width), 0).r);
            vec4 place = texelFetch(levelLights, texel(base, width), 0);  // position, reach
            vec3 toLight = place.xyz - vWorldPos;
            float dist = length(toLight);
            if (dist >= place.w) continue;  // beyond its reach
            vec4 colour = texelFetch(levelLights, texel(base + 1, width), 0);  // irradiance at full strength, formula (+8: spot)
            int formula = int(colour.w + 0.5);
            bool spotlight = formula >= LEVEL_LIGHT_SPOT_FLAG;
            formula -= spotlight ? LEVEL_LIGHT_SPOT_FLAG : 0;
            if (formula == LEVEL_LIGHT_LOCAL_MINIMUM) {
                floorLight = max(floorLight, colour.rgb);
                continue;
            }
            vec3 dir = toLight / max(dist, 1e-4);
            float cosine = dot(n, dir);
            if (cosine <= 0.0) continue;  // behind the surface
            vec4 shape = texelFetch(levelLights, texel(base + 2, width), 0);  // units a metre, gate, anglescale, exponent
            float x = dist * shape.x;  // Quake's scaled distance, map units
            float xi = max(x, LEVEL_MIN_INVERSE_DISTANCE);
            float strength;
            if (formula == LEVEL_LIGHT_LINEAR) {
                strength = clamp(1.0 - dist / place.w, 0.0, 1.0);
                if (shape.w != 1.0) strength = pow(strength, shape.w);  // pow is dear on llvmpipe: Quake's 1 skips it
            } else if (formula == LEVEL_LIGHT_INVERSE) strength = LEVEL_INVERSE_SCALE / xi;
            else if (formula == LEVEL_LIGHT_INVERSE_SQUARE) strength = LEVEL_INVERSE_SCALE * LEVEL_INVERSE_SCALE / (xi * xi);
            else if (formula == LEVEL_LIGHT_INVERSE_SQUARE_A) {
                float s = x + LEVEL_INVERSE_SCALE;
                strength = LEVEL_INVERSE_SCALE * LEVEL_INVERSE_SCALE / (s * s);
            } else strength = 1.0;
            strength = max(strength - shape.y, 0.0);  // the inverse laws' gate (0 for the others)
            strength *= (1.0 - shape.z) + shape.z * cosine;
            if (spotlight) {
                // The cone: 0 outside half its angle, a linear ramp in the cosine up to the soft cone.
                vec4 spot = texelFetch(levelLights, texel(base + 3, width), 0);  // direction, cos of half the soft cone
                float cosOuter = texelFetch(levelLights, texel(base + 4, width), 0).x;
                float c = dot(spot.xyz, -dir);
                strength *= spot.w > cosOuter ? clamp((c - cosOuter) / (spot.w - cosOuter), 0.0, 1.0) : step(cosOuter, c);
            }
            light += colour.rgb * strength;
        }
    }
    light = max(max(light, vec3(0.0)), floorLight);  // negative lights subtract, down to 0
    return light;
}

void main()
{
    vec3 n = normalize(vNormal);
    // 0.7 linear = 0.85 gamma-encoded: the light grey of untextured surfaces.
    vec4 surface = hasAlbedo < 0.5 ? vec4(vec3(pow(0.7, 1.0 / 2.2)), 1.0) : texture(albedoMap, vUv);
    if (surface.a < alphaCutoff) discard;  // a hole: no G-buffer write, so AO and the view see through
    vec3 albedo = surface.rgb;

    vec3 light = vec3(0.0);
    float ndotl = dot(n, sunDirection);
    float sun = sunShare(ndotl);
    float visible = sun > 0.0 ? 1.0 : 0.0;
    if (sun > 0.0 && dot(sunColour, sunColour) > 0.0) visible = sunVisibility(max(ndotl, 0.0));
    vec3 ambient;
    if (baked > 0.5) {
        vec4 lightmap = texture(lightmapDirect, vLightmapUv);
        // 2x: the bake's visibility ramps over a texel at a shadow's edge; doubled, it stays 1 up
        // to the ramp's middle and the shadow map keeps drawing the edge.
        visible *= clamp(2.0 * lightmap.a, 0.0, 1.0);
        light = sunColour * (sun * visible) + lightmap.rgb;
        ambient = texture(lightmapIndirect, vLightmapUv).rgb;
    } else {
        light = gridLights(n, sunColour * (sun * visible));
        ambient = probeAmbient(vWorldPos, n);
    }


    writeGBuffer(albedo, light, visible, ambient, vWorldPos, n);
}
