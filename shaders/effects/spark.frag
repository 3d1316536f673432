#version 330 core
// A soft round glow, added to what is behind it (additive blending, no depth write). In the AO
// modes' G-buffer (OBSCURA_GBUFFER) it adds to the lit colour only: the other targets get zero
// added, so the depth, normal and ambient of the surface behind stay as they were.
in vec4 vColour;
in vec2 vUv;
#ifdef OBSCURA_GBUFFER
layout(location = 0) out vec4 outColour;
layout(location = 1) out vec4 outDepth;
layout(location = 2) out vec4 outNormal;
layout(location = 3) out vec4 outAmbient;
#else
out vec4 outColour;
#endif
void main()
{
    float r = length(vUv * 2.0 - 1.0);
    float glow = clamp(1.0 - r, 0.0, 1.0);
    outColour = vec4(vColour.rgb * vColour.a * glow * glow, 0.0);
#ifdef OBSCURA_GBUFFER
    outDepth = vec4(0.0);
    outNormal = vec4(0.0);
    outAmbient = vec4(0.0);
#endif
}
