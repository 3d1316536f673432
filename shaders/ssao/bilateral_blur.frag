#version 330 core
// Depth-aware (cross-bilateral) blur of the AO term: a 5-tap line along `direction` (separable:
// run horizontally, then vertically), each tap weighted down by its depth difference from the
// centre so occlusion does not bleed across silhouettes. Runs at the AO's resolution.
uniform sampler2D aoMap;
uniform sampler2D gbufferDepth;  // linear depth, metres
uniform vec2 direction;        // one texel of aoMap along x or y
uniform float depthSharpness;  // 1/m: larger keeps edges sharper
in vec2 vUv;
out vec4 fragColour;
void main()
{
    float centreZ = texture(gbufferDepth, vUv).r;
    float sum = 0.0, weights = 0.0;
    for (int i = -2; i <= 2; ++i) {
        vec2 uv = vUv + float(i) * direction;
        float z = texture(gbufferDepth, uv).r;
        float w = exp(-abs(z - centreZ) * depthSharpness) * (3.0 - abs(float(i)));
        sum += texture(aoMap, uv).r * w;
        weights += w;
    }
    fragColour = vec4(vec3(sum / max(weights, 1e-5)), 1.0);
}
