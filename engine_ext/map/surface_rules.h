// What a face's texture name and Quake 2 flags say about how it is drawn, by the rules the Quake
// family's compilers and engines use (plain C++, no OGRE):
// - sky: Quake's engine makes every texture whose name starts with "sky" the sky (Mod_LoadFaces in
//   gl_model.c: `Q_strncmp(name, "sky", 3)`: sky1, sky4, skyb...), case-insensitive here (WAD tools
//   and TrenchBroom also write SKY4), also below a folder (Quake 2's e1u1/sky1, a `wad/` prefix); or
//   a Quake 2 face with SURF_SKY (0x4) in its surface flags.
// - fence: a name starting with '{' is alpha-masked (FitzQuake / QuakeSpasm's SURF_DRAWFENCE, after
//   Half-Life's `{` textures): texels with alpha below 0.5 are holes; the brush still collides, as
//   Quake's fences do.
#pragma once

#include <cstdint>
#include <string_view>

namespace obscura::map {

// Quake 2 surface flags (qfiles.h): the ones the renderer reads.
constexpr std::uint32_t kQ2SurfLight = 0x1, kQ2SurfSky = 0x4, kQ2SurfWarp = 0x8, kQ2SurfTrans33 = 0x10,
                        kQ2SurfTrans66 = 0x20, kQ2SurfNoDraw = 0x80;

// The name after its last folder ("e1u1/sky1" -> "sky1"; '/' or '\\').
std::string_view textureBaseName(std::string_view texture);
// Quake's sky rule on the base name (case-insensitive prefix "sky").
bool isSkyTexture(std::string_view texture);
// Sky by name or, for a Quake 2 face, by SURF_SKY.
bool isSkyFace(std::string_view texture, std::uint32_t surfaceFlags);
// A fence ('{' first in the base name): alpha-tested.
bool isFenceTexture(std::string_view texture);

}  // namespace obscura::map
