#version 330 core
// A soft round glow, added to the frame's HDR light (additive blending, no depth write), drawn in
// the frame's effects queue after the lighting pass (media/frame/frame.compositor).
in vec4 vColour;
in vec2 vUv;
out vec4 outColour;
void main()
{
    float r = length(vUv * 2.0 - 1.0);
    float glow = clamp(1.0 - r, 0.0, 1.0);
    outColour = vec4(vColour.rgb * vColour.a * glow * glow, 0.0);
}
