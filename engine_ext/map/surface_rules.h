// What a face's texture name and Quake 2 flags say about how it is drawn, by the rules the Quake
// family's compilers and engines use (plain C++, no OGRE):
// - sky: Quake's engine makes every texture whose name starts with "sky" the sky (Mod_LoadFaces in
//   gl_model.c: `Q_strncmp(name, "sky", 3)`: sky1, sky4, skyb...), case-insensitive here (WAD tools
//   and TrenchBroom also write SKY4), also below a folder (Quake 2's e1u1/sky1, a `wad/` prefix); or
//   a Quake 2 face with SURF_SKY (0x4) in its surface flags.
// - fence: a name starting with '{' is alpha-masked (FitzQuake / QuakeSpasm's SURF_DRAWFENCE, after
//   Half-Life's `{` textures): texels with alpha below 0.5 are holes; the brush still collides, as
//   Quake's fences do.
// - tool textures (toolSurface): by the base name, so `e1u1/hint` and `common/clip` count, or by
//   Quake 2's content and surface bits; what each does to its face and its brush is ericw-tools'
//   qbsp's (hint and skip: neither drawn nor solid; clip: solid, not drawn; ...).
#pragma once

#include <cstdint>
#include <string_view>

namespace obscura::map {

// Quake 2 surface flags (qfiles.h): the ones the renderer reads.
constexpr std::uint32_t kQ2SurfLight = 0x1, kQ2SurfSky = 0x4, kQ2SurfWarp = 0x8, kQ2SurfTrans33 = 0x10,
                        kQ2SurfTrans66 = 0x20, kQ2SurfNoDraw = 0x80, kQ2SurfHint = 0x100, kQ2SurfSkip = 0x200;
// Quake 2 content bits (qfiles.h) that make a brush a tool brush.
constexpr std::uint32_t kQ2ContentsPlayerClip = 0x10000, kQ2ContentsMonsterClip = 0x20000, kQ2ContentsOrigin = 0x1000000;

// What a tool texture does (none for an ordinary texture).
enum class ToolSurface {
    None,
    Hint,         // hint, hintskip, toolshint, SURF_HINT: a vis splitter; its brush is neither drawn nor solid
    Skip,         // skip, toolsskip, SURF_SKIP: the face is dropped; a brush of hint and skip faces is a hint brush
    Clip,         // clip, playerclip, toolsclip, CONTENTS_PLAYERCLIP: blocks the player, not drawn
    MonsterClip,  // clip_mon, monsterclip, toolsnpcclip, CONTENTS_MONSTERCLIP: blocks monsters only (none here)
    Trigger,      // trigger, toolstrigger: the face of a trigger volume, not drawn
    Origin,       // origin, toolsorigin, CONTENTS_ORIGIN: marks a rotating entity's centre; no geometry
    NoDraw,       // nodraw, caulk, toolsnodraw, SURF_NODRAW, any other common/ or tools/ texture: solid, not drawn
};
// The rule for a face: Quake 2's bits when `quake2Flags` (the face had them), else the name.
ToolSurface toolSurface(std::string_view texture, bool quake2Flags = false, std::uint32_t contents = 0, std::uint32_t surfaceFlags = 0);

// The name after its last folder ("e1u1/sky1" -> "sky1"; '/' or '\\').
std::string_view textureBaseName(std::string_view texture);
// Quake's sky rule on the base name (case-insensitive prefix "sky").
bool isSkyTexture(std::string_view texture);
// Sky by name or, for a Quake 2 face, by SURF_SKY.
bool isSkyFace(std::string_view texture, std::uint32_t surfaceFlags);
// A fence ('{' first in the base name): alpha-tested.
bool isFenceTexture(std::string_view texture);

}  // namespace obscura::map
