#version 330 core
// Shows one of the frame's buffers as it is stored (engine_ext/gbuffer_view): 0 albedo, 1 the
// view-space normal (packed to 0..1), 2 linear depth on a log scale (white at 0.25 m, a step of
// grey each doubling, black at 64 m; sky black: a linear 0..50 m ramp left a room almost white),
// 3 the direct light and 4 the HDR light, both divided by 4 (so 1.0 shows as a quarter grey).
uniform sampler2D gbufferAlbedo;
uniform sampler2D gbufferNormal;
uniform sampler2D gbufferDepth;
uniform sampler2D gbufferLight;
uniform sampler2D litMap;
uniform float view;
in vec2 vUv;
out vec4 fragColour;
void main()
{
    ivec2 size = textureSize(gbufferDepth, 0);
    ivec2 pixel = clamp(ivec2(vUv * vec2(size)), ivec2(0), size - 1);
    int v = int(view + 0.5);
    vec3 c;
    if (v == 0) c = texelFetch(gbufferAlbedo, pixel, 0).rgb;
    else if (v == 1) c = texelFetch(gbufferNormal, pixel, 0).rgb;
    else if (v == 2) {
        float d = texelFetch(gbufferDepth, pixel, 0).r;
        c = vec3(d > 0.0 ? 1.0 - clamp(log2(d / 0.25) / 8.0, 0.0, 1.0) : 0.0);
    } else if (v == 3) c = pow(texelFetch(gbufferLight, pixel, 0).rgb / 4.0, vec3(1.0 / 2.2));
    else c = pow(texelFetch(litMap, pixel, 0).rgb / 4.0, vec3(1.0 / 2.2));
    fragColour = vec4(clamp(c, 0.0, 1.0), 1.0);
}
