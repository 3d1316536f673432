#version 330 core
// Translucent liquid surfaces (water, slime, lava, teleporters), drawn forward into the frame's
// HDR light `lit` after the lighting pass (render queue frame::kLiquidQueue), hidden behind the
// opaque scene by the G-buffer's depth. Both sides are drawn (the geometry holds each face twice, the back one facing in), so the
// surface shows from above and from below.
//   - Quake's turbulent warp (gl_warp.c, WARPCALC): each texture coordinate swings by 1/8 of the
//     texture (8 of 64 texels) with the sine of the other coordinate x 8 plus the time, so the
//     ripples roll; the time is the simulation's (liquidTime), so a replay draws the same frames.
//   - lit by the level's hemispheric ambient and the sun (no shadow: water scatters it); lava and
//     teleporters glow (Quake draws them full bright);
//   - a Fresnel reflection of the sky ambient (Schlick, water's F0 = 0.02) brightens and
//     thickens the surface at grazing angles;
//   - seen from inside a liquid (mediumDensity > 0), the surface mirrors the water beyond the
//     critical angle, and is fogged by its own distance
//     here (the output pass tints the whole view), and its pixel is marked (alpha 0 in `lit`, through the blend's alpha factors)
//     so the output pass does not fog it again by the depth of what lies behind it.
uniform sampler2D albedoMap;
uniform sampler2D gbufferDepth;  // the opaque scene's linear view depth, 0 = sky (engine_ext/frame)
uniform mat4 view;               // world -> view
uniform float alpha;          // opacity, 0..1 (map/liquid.h: the alpha keys)
uniform float glow;           // 1: lava / teleporter, emissive
uniform vec3 cameraPosition;
uniform vec3 sunDirection;    // ObscuraLighting
uniform vec3 sunColour;
#include "baked_ambient.glsl"  // lightProbes, probeAmbient (and the hemisphere's skyAmbient, groundAmbient)
uniform float liquidTime;     // ObscuraLiquid: seconds of simulation
uniform vec3 mediumTint;      // ObscuraLiquid: the camera's liquid, or none (density 0)
uniform vec3 mediumFog;
uniform float mediumDensity;

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
out vec4 fragColour;

// Quake's warp: amplitude 8 texels of a 64-texel texture, phase 8 per texture repeat.
const float kWarpAmplitude = 0.125;
const float kWarpFrequency = 8.0;
// Glow of lava and teleporters: their texture's colour x 2 reads as self-lit through the tone map
// (exposure 1.6: orange lava lands near sRGB 0.8).
const float kGlow = 2.0;
const float kWaterF0 = 0.02;  // reflectance of water at normal incidence (index 1.33)

void main()
{
    // Behind the opaque scene: hidden (the pass has no hardware depth test; see the material).
    // `lit` and the G-buffer are render textures of one size: the same pixel in both.
    float scene = texelFetch(gbufferDepth, ivec2(gl_FragCoord.xy), 0).r;
    float here = -(view * vec4(vWorldPos, 1.0)).z;
    if (scene > 0.0 && here > scene * (1.0 + 1e-4) + 1e-3) discard;
    vec2 uv = vUv + kWarpAmplitude * sin(vUv.yx * kWarpFrequency + vec2(liquidTime));
    vec3 albedo = pow(texture(albedoMap, uv).rgb, vec3(2.2));
    vec3 n = normalize(vNormal);
    vec3 toEye = cameraPosition - vWorldPos;
    float dist = length(toEye);
    vec3 v = toEye / max(dist, 1e-4);

    vec3 ambient = probeAmbient(vWorldPos, n);
    vec3 light = ambient + sunColour * max(dot(n, sunDirection), 0.0);
    vec3 colour = albedo * (light + glow * kGlow);
    float fresnel = kWaterF0 + (1.0 - kWaterF0) * pow(1.0 - clamp(dot(n, v), 0.0, 1.0), 5.0);
    // The reflection: the light from above here (the sky where the sky is seen, a ceiling's bounce indoors).
    colour = mix(colour, probeAmbient(vWorldPos, vec3(0.0, 1.0, 0.0)), fresnel * (1.0 - glow));
    float a = mix(alpha, 1.0, fresnel);

    if (mediumDensity > 0.0) {
        // From inside, past the critical angle (48.6 degrees from the normal for water to air,
        // cos = 0.66) the surface reflects the water below it wholly (total internal reflection):
        // a bright window overhead in a water-coloured ceiling (Snell's window).
        float window = smoothstep(0.6, 0.72, abs(dot(n, v)));
        colour = mix(mediumFog * 2.0, colour, window);
        a = mix(1.0, a, window);
        // out = src * A + dst * (1 - A) must equal fog(a * colour + (1 - a) * dst) by this
        // surface's distance (the output pass tints the whole view, this pixel too).
        float keep = exp(-mediumDensity * dist);
        float blend = 1.0 - keep * (1.0 - a);
        vec3 src = (keep * a * colour + (1.0 - keep) * mediumFog) / max(blend, 1e-4);
        fragColour = vec4(src, blend);
        return;
    }
    fragColour = vec4(colour, a);
}
