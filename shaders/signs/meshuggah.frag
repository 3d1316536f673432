#version 330 core
// `--sign-mode meshuggah` (engine_ext/signs/meshuggah.h): a ray of a sign's 8-bit mask, added into
// the frame's HDR `lit`. Across the strip the seed's 1D black-white-black gradient (a tent: the
// neighbours' tents, one texel apart, add up to 1), times the mask's 8-bit value; along it the
// light the haze scatters from that texel's cone of the beam: haze x irradiance (sign_light.glsl's
// law: inverse square, faded to 0 at the range) x the haze's phase x the cone's width (the path a
// view ray crossing the beam spends in one texel's cone). Hidden behind the opaque scene by the
// G-buffer's depth (the hardware depth buffer bound with `lit` is not the scene's on llvmpipe:
// liquid.frag), and cut where the lamp's shadow map saw the first surface (walls, the pillar).
in vec3 vWorldPos;
in float vAcross;
in float vLampDistance;
in float vCoverage;
in float vHalfWidth;
in vec3 vDirection;
uniform sampler2D gbufferDepth;  // the opaque scene's linear view depth, 0 = sky (engine_ext/frame)
uniform sampler2D rayShadow;     // PF_FLOAT32_R: distance from the lamp (m), 0 = nothing
uniform mat4 view;
uniform vec3 cameraPosition;
uniform vec4 rayLamp;            // the lamp's centre (world), w = its radius (m)
uniform vec4 rayColour;          // linear colour x intensity, w = range (m)
uniform float rayHaze;           // per metre
uniform mat4 rayShadowMatrix;    // world -> the shadow map's clip space
uniform float rayShadowOn;
out vec4 fragColour;
#include "volume_phase.glsl"
const float kSignG = 0.3;        // as sign_march.glsl's haze
const float kShadowBias = 0.05;  // as sign_light.glsl's kSignShadowBias

void main()
{
    float scene = texelFetch(gbufferDepth, ivec2(gl_FragCoord.xy), 0).r;
    float here = -(view * vec4(vWorldPos, 1.0)).z;
    if (scene > 0.0 && here > scene * (1.0 + 1e-4) + 1e-3) discard;
    if (rayShadowOn > 0.0) {
        vec4 clip = rayShadowMatrix * vec4(vWorldPos, 1.0);
        if (clip.w > 0.0) {
            vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
            if (all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)))) {
                float stored = texture(rayShadow, uv).r;
                if (stored > 0.0 && vLampDistance > stored + kShadowBias) discard;
            }
        }
    }
    float f = vLampDistance / rayColour.w;
    float w = clamp(1.0 - f * f * f * f, 0.0, 1.0);
    float r = max(vLampDistance, rayLamp.w);
    float tent = max(1.0 - abs(vAcross), 0.0);
    float phase = volumePhase(dot(normalize(vWorldPos - cameraPosition), vDirection), kSignG);
    vec3 light = rayColour.rgb * (w * w / (r * r)) * rayHaze * phase * vHalfWidth * vCoverage * tent;
    fragColour = vec4(light, 0.0);
}
