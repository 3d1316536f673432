#version 330 core
// The back-lit signs' lettered light on the level's surfaces (engine_ext/signs), added into `lit`
// after the lighting pass: for every pixel its world position from the G-buffer's depth, and
// albedo x (the irradiance the signs' lamps give it through their letters, sign_light.glsl) x the
// cosine to the lamp. The same light the shafts scatter (shaders/signs/sign_march.glsl).
#include "frame_shared.h"
#include "signs_shared.h"
#include "sign_light.glsl"
#include "view_ray.glsl"
uniform sampler2D gbufferAlbedo;
uniform sampler2D gbufferNormal;
uniform sampler2D gbufferDepth;
uniform sampler2D decalAlbedo;   // premultiplied decal albedo (gamma) + coverage, or 1x1 clear
in vec2 vUv;
out vec4 fragColour;

void main()
{
    ivec2 size = textureSize(gbufferDepth, 0);
    ivec2 pixel = clamp(ivec2(vUv * vec2(size)), ivec2(0), size - 1);
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    if (depth <= 0.0 || signCount < 0.5) {
        fragColour = vec4(0.0);
        return;
    }
    vec3 viewPos = viewRayAt(vUv) * depth;
    vec3 p = (inverseView * vec4(viewPos, 1.0)).xyz;
    vec3 n = normalize(mat3(inverseView) * (texelFetch(gbufferNormal, pixel, 0).xyz * 2.0 - 1.0));
    // 2 cm off the surface: the shadow map's texel and its depth's rounding stay behind it.
    p += n * 0.02;
    vec3 irradiance = vec3(0.0);
    int count = int(signCount);
    for (int i = 0; i < SIGN_MAX_LIGHTS; ++i) {
        if (i >= count) break;
        vec3 toLamp;
        vec3 e = signIrradiance(i, p, toLamp);
        irradiance += e * max(dot(n, toLamp), 0.0);
    }
    // The albedo only where some light arrives (most pixels get none: three reads saved).
    if (all(equal(irradiance, vec3(0.0)))) {
        fragColour = vec4(0.0);
        return;
    }
    vec4 decal = texelFetch(decalAlbedo, min(pixel, textureSize(decalAlbedo, 0) - 1), 0);
    vec3 albedo = pow(texelFetch(gbufferAlbedo, pixel, 0).rgb * (1.0 - decal.a) + decal.rgb, vec3(2.2));
    fragColour = vec4(albedo * irradiance, 0.0);
}
