#version 330 core
// The frame's output pass: the volumes (smoke) over the light, the exposure, and the one tone map
// of the frame (exponential: never clips hard), gamma 2.2 for the display. Or the AO alone.
// With the camera inside a liquid (mediumDensity > 0, ObscuraLiquid), the light is first fogged
// by each pixel's depth — except where a translucent liquid surface lies (alpha 0 in `lit`): that
// surface fogged itself by its own distance (shaders/level/liquid.frag) — then tinted.
#include "frame_shared.h"
#include "upsample.glsl"
uniform sampler2D litMap;        // HDR light (lighting pass and effects)
uniform sampler2D volumeMap;     // rgb in-scattered light (HDR), a transmittance, at FRAME_VOLUME_SCALE
uniform sampler2D gbufferDepth;
uniform sampler2D aoMap;
uniform float exposure;
uniform float view;              // frame::View: 0 the scene, 1 the AO alone
uniform float aoPresent;
uniform float volumePresent;     // 0: no volumes this frame, volumeMap is not read
uniform vec3 mediumTint;         // ObscuraLiquid: the camera's liquid (tint x, fog colour, density /m)
uniform vec3 mediumFog;
uniform float mediumDensity;
in vec2 vUv;
out vec4 fragColour;

void main()
{
    ivec2 size = textureSize(gbufferDepth, 0);
    ivec2 pixel = clamp(ivec2(vUv * vec2(size)), ivec2(0), size - 1);
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    if (view > 0.5) {
        float ao = depth > 0.0 && aoPresent > 0.5 ? upsampledAo(aoMap, vUv, depth) : 1.0;
        fragColour = vec4(vec3(ao), 1.0);
        return;
    }
    vec4 lit = texelFetch(litMap, pixel, 0);
    vec3 light = lit.rgb;
    if (mediumDensity > 0.0) {
        // Depth 0 (the sky) is far: the fog swallows it. A liquid surface fogged itself.
        float keep = depth > 0.0 ? exp(-mediumDensity * depth) : 0.0;
        if (lit.a > 0.5) light = mix(mediumFog, light, keep);
        light *= mediumTint;  // the view's tint (Quake's v_cshift), over everything
    }
    if (volumePresent > 0.5) {
        vec4 volume = upsampledVolume(volumeMap, gbufferDepth, vUv, depth);
        light = light * volume.a + volume.rgb;
    }
    fragColour = vec4(pow(vec3(1.0) - exp(-light * exposure), vec3(1.0 / 2.2)), 1.0);
}
