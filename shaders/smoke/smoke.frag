#version 330 core
// The smoke grenades' volumes, ray-marched at half resolution (smoke_march.glsl) against the
// G-buffer's linear depth: writes the in-scattered light (linear HDR) and the transmittance; the
// frame's output pass upsamples them depth-aware and lays them over the light.
uniform sampler2D gbufferDepth;  // linear depth at full resolution (bound by the frame)
uniform vec2 projScale;      // projection matrix [0][0] and [1][1]
uniform float flipY;         // 1 when render textures are stored upside down
uniform mat4 inverseView;    // view -> world
in vec2 vUv;
out vec4 fragColour;
#include "smoke_march.glsl"
void main()
{
    vec3 light = vec3(0.0);
    float transmittance = 1.0;
    if (smokeCount > 0.5) {
        ivec2 size = textureSize(gbufferDepth, 0);
        float depth = texelFetch(gbufferDepth, clamp(ivec2(vUv * vec2(size)), ivec2(0), size - 1), 0).r;
        vec2 ndc = vec2(vUv.x, flipY > 0.5 ? 1.0 - vUv.y : vUv.y) * 2.0 - 1.0;
        vec3 viewDir = normalize(vec3(ndc / projScale, -1.0));
        float maxT = depth > 0.0 ? depth / -viewDir.z : 1e4;
        // Interleaved gradient noise (Jimenez 2014): the start jitter, stable from frame to frame.
        float jitter = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
        marchSmoke(inverseView[3].xyz, normalize(mat3(inverseView) * viewDir), maxT, jitter, light, transmittance);
    }
    fragColour = vec4(light, transmittance);
}
