#version 330 core
// The volumetrics' resolved buffer kept for the next frame's resolve (volume_resolve.frag).
uniform sampler2D volumeResolved;
in vec2 vUv;
out vec4 fragColour;
void main()
{
    ivec2 size = textureSize(volumeResolved, 0);
    fragColour = texelFetch(volumeResolved, min(ivec2(vUv * vec2(size)), size - 1), 0);
}
