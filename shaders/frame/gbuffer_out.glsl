// Writes the frame's G-buffer (layout: frame_shared.h). Every opaque material's GBuffer-scheme
// fragment program includes this and calls writeGBuffer once. On a GPU with fewer than
// FRAME_GBUFFER_TARGETS render targets the frame draws the scene twice, and compiles the program
// with FRAME_GBUFFER_PART 0 (albedo, normal) or 1 (depth, light, ambient): the other outputs are then plain
// variables the compiler drops.
#include "frame_shared.h"
uniform mat4 view;  // world -> view (OGRE view_matrix)
#if !defined(FRAME_GBUFFER_PART)
layout(location = FRAME_GBUFFER_ALBEDO) out vec4 outAlbedo;
layout(location = FRAME_GBUFFER_NORMAL) out vec4 outNormal;
layout(location = FRAME_GBUFFER_DEPTH) out vec4 outDepth;
layout(location = FRAME_GBUFFER_LIGHT) out vec4 outLight;
layout(location = FRAME_GBUFFER_AMBIENT) out vec4 outAmbient;
#elif FRAME_GBUFFER_PART == 0
layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormal;
vec4 outDepth, outLight, outAmbient;
#else
vec4 outAlbedo, outNormal;
layout(location = 0) out vec4 outDepth;
layout(location = 1) out vec4 outLight;
layout(location = 2) out vec4 outAmbient;
#endif

// albedo: gamma-encoded, as textures store it; directLight: linear irradiance, HDR; sunVisible:
// the fraction of the sun its shadow lets through here (0 on faces turned from it), which the
// lighting pass needs to relight a normal a decal bends; ambient: the indirect irradiance, linear.
void writeGBuffer(vec3 albedo, vec3 directLight, float sunVisible, vec3 ambient, vec3 worldPos, vec3 worldNormal)
{
    outAlbedo = vec4(albedo, 1.0);
    outNormal = vec4(normalize(mat3(view) * worldNormal) * 0.5 + 0.5, 0.5 + 0.5 * worldNormal.y);
    outDepth = vec4(-(view * vec4(worldPos, 1.0)).z, 0.0, 0.0, 1.0);
    outLight = vec4(directLight, sunVisible);
    outAmbient = vec4(ambient, 1.0);
}
