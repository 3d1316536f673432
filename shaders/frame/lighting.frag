#version 330 core
// The frame's lighting pass: the light each visible surface sends to the eye, linear and HDR, into
// the float target `lit`:  albedo x (direct light + ambient x AO).
// The direct light (sun with its shadow, point lights) and the ambient (the baked indirect light,
// engine_ext/lightbake) arrive as irradiance in the G-buffer; AO darkens the ambient term only. Decals change the albedo and may bend the normal first. Sky pixels (depth 0) keep their colour as shown: the tone map is
// undone for them here, so the output pass shows them unchanged.
#include "frame_shared.h"
#include "upsample.glsl"
#include "sun_share.glsl"
#include "view_ray.glsl"
uniform sampler2D gbufferAlbedo;
uniform sampler2D gbufferNormal;
uniform sampler2D gbufferDepth;
uniform sampler2D gbufferLight;
uniform sampler2D gbufferAmbient;
uniform sampler2D aoMap;        // (AO, depth) at the AO's resolution (engine_ext/ssao), or 1x1 open
uniform sampler2D decalAlbedo;  // premultiplied decal albedo (gamma) + coverage (engine_ext/decals), or 1x1 clear
uniform sampler2D decalNormal;  // premultiplied world normal + coverage (engine_ext/decals), or 1x1 clear
uniform mat4 view;              // world -> view of the camera that drew the G-buffer
uniform vec3 sunDirection;      // world, unit, towards the sun (ObscuraLighting)
uniform vec3 sunColour;         // linear RGB (ObscuraLighting)
uniform float aoPresent;        // 0: no AO stage runs, AO is 1 everywhere
uniform float exposure;         // the output's, to undo the tone map for the sky
uniform float ambientAreaCount; // the level's env_ambient boxes (Frame::setAmbientAreas)
uniform vec4 ambientAreaMin[FRAME_MAX_AMBIENT_AREAS];  // xyz the box's low corner (world), w its ambient scale
uniform vec4 ambientAreaMax[FRAME_MAX_AMBIENT_AREAS];  // xyz the high corner, w the blend across its faces (m)
in vec2 vUv;
out vec4 fragColour;

// map_lights.cpp's ambientScaleAt: the ambient's factor at world point p (1 outside every area).
float ambientScaleAt(vec3 p)
{
    float factor = 1.0;
    for (int i = 0; i < FRAME_MAX_AMBIENT_AREAS; ++i) {
        if (float(i) >= ambientAreaCount) break;
        vec3 lo = p - ambientAreaMin[i].xyz, hi = ambientAreaMax[i].xyz - p;
        float inside = min(min(min(lo.x, hi.x), min(lo.y, hi.y)), min(lo.z, hi.z)) + FRAME_AMBIENT_AREA_GRACE;
        float blend = ambientAreaMax[i].w;
        float w = blend > 0.0 ? clamp(0.5 + inside / blend, 0.0, 1.0) : (inside >= 0.0 ? 1.0 : 0.0);
        factor = min(factor, 1.0 + (ambientAreaMin[i].w - 1.0) * w);
    }
    return factor;
}

void main()
{
    // From the quad's uv, not gl_FragCoord: the viewport may be a window while the G-buffer is a
    // render texture stored upside down, and the uv accounts for that.
    ivec2 size = textureSize(gbufferDepth, 0);
    ivec2 pixel = clamp(ivec2(vUv * vec2(size)), ivec2(0), size - 1);
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    vec3 albedo = pow(texelFetch(gbufferAlbedo, pixel, 0).rgb, vec3(2.2));
    if (depth <= 0.0) {
        // 1/1024: white stays finite when undone (1 - exp(-x) reaches 1 - 1/1024 at x = 6.9).
        fragColour = vec4(-log(max(vec3(1.0) - albedo, vec3(1.0 / 1024.0))) / exposure, 1.0);
        return;
    }
    // Decals over the albedo, before any light (so the sun, AO and the smoke all see them).
    ivec2 decalSize = textureSize(decalAlbedo, 0);
    vec4 decal = texelFetch(decalAlbedo, min(pixel, decalSize - 1), 0);
    vec3 gammaAlbedo = texelFetch(gbufferAlbedo, pixel, 0).rgb * (1.0 - decal.a) + decal.rgb;
    albedo = pow(gammaAlbedo, vec3(2.2));
    float ao = aoPresent > 0.5 ? upsampledAo(aoMap, vUv, depth) : 1.0;
    vec4 light = texelFetch(gbufferLight, pixel, 0);
    vec3 direct = light.rgb;
    // A decal's bent normal (a bullet hole's crater and rim): the sun's share relit with it (its
    // shadow as the G-buffer pass found it). Point lights and the ambient keep the surface's own
    // normal (the G-buffer holds only their sums). Pixels no decal bends keep the G-buffer's light
    // to the bit.
    vec4 bent = texelFetch(decalNormal, min(pixel, textureSize(decalNormal, 0) - 1), 0);
    if (bent.a > 0.0) {
        vec3 nView = texelFetch(gbufferNormal, pixel, 0).xyz * 2.0 - 1.0;
        vec3 n = normalize(transpose(mat3(view)) * nView);
        vec3 nBent = normalize(n * (1.0 - bent.a) + bent.rgb);
        direct += sunColour * (light.a * (sunShare(dot(nBent, sunDirection)) - sunShare(dot(n, sunDirection))));
        direct = max(direct, vec3(0.0));
    }
    vec3 ambient = texelFetch(gbufferAmbient, pixel, 0).rgb;
    if (ambientAreaCount > 0.5) {
        vec3 world = (inverseView * vec4(viewRayAt(vUv) * depth, 1.0)).xyz;
        ambient *= ambientScaleAt(world);
    }
    fragColour = vec4(albedo * (direct + ambient * ao), 1.0);
}
