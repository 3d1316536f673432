#version 330 core
// The truth key's picture over the frame (engine_ext/ao_truth): truthShow 1 the uploaded
// reference or heat map, 2 the AO buffer's AO (red; its pixels, as the mode is scored).
uniform sampler2D truthMap;
uniform sampler2D aoMap;
uniform float truthShow;
in vec2 vUv;
out vec4 fragColour;
void main()
{
    vec3 c;
    if (truthShow > 1.5) {
        ivec2 size = textureSize(aoMap, 0);
        c = vec3(texelFetch(aoMap, clamp(ivec2(vUv * vec2(size)), ivec2(0), size - 1), 0).r);
    } else {
        ivec2 size = textureSize(truthMap, 0);
        c = texelFetch(truthMap, clamp(ivec2(vUv * vec2(size)), ivec2(0), size - 1), 0).rgb;
    }
    fragColour = vec4(c, 1.0);
}
