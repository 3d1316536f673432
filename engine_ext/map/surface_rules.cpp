// See surface_rules.h.
#include "map/surface_rules.h"

#include <cctype>
#include <string>

namespace obscura::map {

std::string_view textureBaseName(std::string_view texture) {
    const auto slash = texture.find_last_of("/\\");
    return slash == std::string_view::npos ? texture : texture.substr(slash + 1);
}

bool isSkyTexture(std::string_view texture) {
    const std::string_view b = textureBaseName(texture);
    if (b.size() < 3) return false;
    const char* sky = "sky";
    for (int i = 0; i < 3; ++i)
        if (std::tolower(static_cast<unsigned char>(b[static_cast<std::size_t>(i)])) != sky[i]) return false;
    return true;
}

bool isSkyFace(std::string_view texture, std::uint32_t surfaceFlags) {
    return (surfaceFlags & kQ2SurfSky) != 0 || isSkyTexture(texture);
}

bool isFenceTexture(std::string_view texture) {
    const std::string_view b = textureBaseName(texture);
    return !b.empty() && b.front() == '{';
}

namespace {
std::string lowerCase(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}
}  // namespace

ToolSurface toolSurface(std::string_view texture, bool quake2Flags, std::uint32_t contents, std::uint32_t surfaceFlags) {
    if (quake2Flags) {
        if (contents & kQ2ContentsOrigin) return ToolSurface::Origin;
        if (surfaceFlags & kQ2SurfHint) return ToolSurface::Hint;
        if (surfaceFlags & kQ2SurfSkip) return ToolSurface::Skip;
        if (contents & kQ2ContentsPlayerClip) return ToolSurface::Clip;
        if (contents & kQ2ContentsMonsterClip) return ToolSurface::MonsterClip;
        if (surfaceFlags & kQ2SurfNoDraw) return ToolSurface::NoDraw;
    }
    const std::string full = lowerCase(texture);
    const std::string base = lowerCase(textureBaseName(texture));
    // Quake's and Quake 2's names, Quake 3's common/, Source's tools/ (toolsX).
    const std::string name = base.rfind("tools", 0) == 0 && full.rfind("tools/", 0) == 0 ? base.substr(5) : base;
    if (name == "hint" || name == "hintskip") return ToolSurface::Hint;
    if (name == "skip") return ToolSurface::Skip;
    if (name == "clip" || name == "playerclip" || name == "clip_player" || name == "fullclip") return ToolSurface::Clip;
    if (name == "clip_mon" || name == "clipmon" || name == "monsterclip" || name == "clip_monster" || name == "npcclip")
        return ToolSurface::MonsterClip;
    if (name == "trigger") return ToolSurface::Trigger;
    if (name == "origin") return ToolSurface::Origin;
    if (name == "nodraw" || name == "caulk" || full.rfind("common/", 0) == 0 || full.rfind("tools/", 0) == 0) return ToolSurface::NoDraw;
    return ToolSurface::None;
}

}  // namespace obscura::map
