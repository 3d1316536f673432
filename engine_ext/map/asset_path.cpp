// See asset_path.h.
#include "map/asset_path.h"

#include <filesystem>

namespace obscura::map {

namespace fs = std::filesystem;

namespace {
bool within(const fs::path& file, const fs::path& root) {
    auto f = file.begin();
    for (auto r = root.begin(); r != root.end(); ++r, ++f) {
        if (r->empty()) continue;  // a trailing separator
        if (f == file.end() || *f != *r) return false;
    }
    return true;
}
}  // namespace

std::vector<std::string> levelAssetRoots(const std::string& levelPath, const std::vector<std::string>& searchDirs) {
    const fs::path levelDir = fs::path(levelPath).parent_path();
    std::vector<std::string> roots = {(levelDir.empty() ? fs::path(".") : levelDir).string()};
    for (const std::string& dir : searchDirs) {
        roots.push_back((fs::path(dir) / "media").string());
        roots.push_back((fs::path(dir) / ".." / "shared").string());
    }
    return roots;
}

bool isBareName(const std::string& name) {
    return !name.empty() && name.find('/') == std::string::npos && name.find('\\') == std::string::npos && name != "." &&
           name != "..";
}

AssetPath resolveAsset(const std::string& name, const std::vector<std::string>& searchDirs, const std::vector<std::string>& roots) {
    AssetPath out;
    if (name.empty()) return out;
    std::error_code ec;
    fs::path found;
    if (fs::path(name).is_absolute()) {
        if (fs::is_regular_file(name, ec)) found = name;
    } else {
        for (const std::string& dir : searchDirs) {
            const fs::path candidate = fs::path(dir) / name;
            if (fs::is_regular_file(candidate, ec)) {
                found = candidate;
                break;
            }
        }
    }
    if (found.empty()) return out;
    const fs::path file = fs::canonical(found, ec);
    if (ec) {
        out.error = "cannot be resolved (" + ec.message() + ")";
        return out;
    }
    for (const std::string& r : roots) {
        std::error_code rec;
        const fs::path root = fs::canonical(r, rec);
        if (!rec && within(file, root)) {
            out.file = file.string();
            return out;
        }
    }
    out.error = "resolves to '" + file.string() + "', outside the level's folder and the media folders";
    return out;
}

}  // namespace obscura::map
