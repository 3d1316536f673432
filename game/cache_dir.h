// Where the game keeps what it can make again (its log, the light bake's cache):
// $XDG_CACHE_HOME/obscura, else ~/.cache/obscura (the suite points XDG_CACHE_HOME into the build tree).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

namespace obscura {

inline std::string cacheDir() {
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    return (std::filesystem::path(xdg && *xdg ? xdg : std::string(home ? home : "/tmp") + "/.cache") / "obscura").string();
}

}  // namespace obscura
