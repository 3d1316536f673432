// The AO modes' G-buffer, written by the main lighting pass itself in the GBuffer material scheme
// (media/ssao/ssao.compositor, Obscura/SSAO/GBuffer), so the scene is drawn once per frame:
//   0: the lit colour, tone-mapped exactly as the plain view shows it (8 bits a channel)
//   1: linear view depth in metres, 0 = nothing drawn (32-bit: 16 bits are centimetres off at 30 m)
//   2: the view-space normal packed to 0..1 (8 bits a channel)
//   3: the ambient share of colour 0's light per channel, 0..1: all AO may take away (8 bits)
// Only 8-bit and 32-bit float targets: llvmpipe converts 16-bit floats in software, and with
// 16-bit float colour and ambient targets the G-buffer cost about twice as much.
uniform mat4 view;  // world -> view (OGRE view_matrix)
layout(location = 0) out vec4 outColour;
layout(location = 1) out vec4 outDepth;
layout(location = 2) out vec4 outNormal;
layout(location = 3) out vec4 outAmbient;

void writeGBuffer(vec3 hdrColour, vec3 hdrAmbient, vec3 worldPos, vec3 worldNormal)
{
    outColour = vec4(pow(vec3(1.0) - exp(-hdrColour), vec3(1.0 / 2.2)), 1.0);  // level.frag's tone map
    outDepth = vec4(-(view * vec4(worldPos, 1.0)).z, 0.0, 0.0, 1.0);
    outNormal = vec4(normalize(mat3(view) * worldNormal) * 0.5 + 0.5, 1.0);
    outAmbient = vec4(clamp(hdrAmbient / max(hdrColour, vec3(1e-4)), 0.0, 1.0), 1.0);
}
