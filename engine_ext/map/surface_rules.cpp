// See surface_rules.h.
#include "map/surface_rules.h"

#include <cctype>

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

}  // namespace obscura::map
