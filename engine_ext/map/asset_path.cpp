// See asset_path.h.
#include "map/asset_path.h"

#include "map/entity_values.h"

#include <filesystem>
#include <stdexcept>
#include <utility>

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

std::vector<std::string> levelSearchDirs(const std::string& levelPath, const std::string& dataDir) {
    return {fs::path(levelPath).parent_path().string(), dataDir, fs::current_path().string()};
}

std::vector<std::string> levelAssetRoots(const std::string& levelPath, const std::vector<std::string>& searchDirs) {
    const fs::path levelDir = fs::path(levelPath).parent_path();
    std::vector<std::string> roots = {(levelDir.empty() ? fs::path(".") : levelDir).string()};
    for (const std::string& dir : searchDirs) roots.push_back((fs::path(dir) / "media").string());
    return roots;
}

LevelFiles::LevelFiles(const std::string& levelPath, std::vector<std::string> searchDirs)
    : searchDirs_(std::move(searchDirs)), roots_(levelAssetRoots(levelPath, searchDirs_)) {}

std::string LevelFiles::require(const std::string& name, const std::string& where, const std::string& what) const {
    const AssetPath found = find(name);
    const std::string shown = where + " " + what + " " + quotedValue(name);
    if (!found.error.empty()) throw std::runtime_error(shown + " " + found.error + "; a level's files must live there");
    if (found.file.empty())
        throw std::runtime_error(shown + " not found (looked in the level's folder, the data folder and the working directory)");
    return found.file;
}

bool isBareName(const std::string& name) {
    return !name.empty() && name.find('/') == std::string::npos && name.find('\\') == std::string::npos && name != "." &&
           name != "..";
}

AssetPath resolveAsset(const std::string& name, const std::vector<std::string>& searchDirs, const std::vector<std::string>& roots,
                       const std::string& rootsName) {
    AssetPath out;
    if (name.empty()) return out;
    std::error_code ec;
    fs::path found;
    // exists() follows symlinks; a dangling link is no file. Nothing here opens the file.
    if (fs::path(name).is_absolute()) {
        if (fs::exists(name, ec)) found = name;
    } else {
        for (const std::string& dir : searchDirs) {
            const fs::path candidate = fs::path(dir) / name;
            if (fs::exists(candidate, ec)) {
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
        if (rec || !within(file, root)) continue;
        if (fs::is_regular_file(file, rec))
            out.file = file.string();
        else
            out.error = "resolves to '" + file.string() + "', which is " + (fs::is_directory(file, rec) ? "a folder" : "no regular file (a device or a FIFO)");
        return out;
    }
    out.error = "resolves to '" + file.string() + "', outside " + rootsName;
    return out;
}

}  // namespace obscura::map
