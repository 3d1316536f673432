// The one lookup of every file a level names: misc_model meshes (colliders, renderer, the
// reference tools), decal_sign images, light_sign fonts and the level's `.ent` overlay. A level may
// only reach files inside its own folder and the game's media folders, whatever `..`, absolute
// paths or symlinks it uses, and only regular files: a device, a FIFO or a folder is refused before
// anything opens it. Plain C++ (std::filesystem); the OGRE glue calls it before OGRE sees a path.
#pragma once

#include <string>
#include <vector>

namespace obscura::map {

struct AssetPath {
    std::string file;   // canonical path of the file found inside a root; empty if none
    std::string error;  // why the name is refused (outside every root, not a regular file); empty if not refused
};

// Looks for `name`: as is when absolute, else relative to each of `searchDirs` in turn. The first
// that exists is resolved (symlinks and `..`) and must lie inside one of `roots` (themselves
// resolved; missing roots are ignored) and be a regular file, else `error` says what it is. A name
// that exists nowhere gives neither (the caller may look a bare name up elsewhere). `rootsName`
// names the roots in the error.
AssetPath resolveAsset(const std::string& name, const std::vector<std::string>& searchDirs, const std::vector<std::string>& roots,
                       const std::string& rootsName = "the level's folder and the media folders");

// The folders a level's relative names are tried in, in order: the level's folder, the data folder
// (the checkout or the installed share folder) and the working directory.
std::vector<std::string> levelSearchDirs(const std::string& levelPath, const std::string& dataDir);

// The roots a level's files may resolve into: the level's folder and `media/` of each search
// folder (the third-party data the tests use is vendored in media/third_party/).
std::vector<std::string> levelAssetRoots(const std::string& levelPath, const std::vector<std::string>& searchDirs);

// A level's files: its search folders and roots, worked out once.
class LevelFiles {
public:
    LevelFiles(const std::string& levelPath, std::vector<std::string> searchDirs);
    AssetPath find(const std::string& name) const { return resolveAsset(name, searchDirs_, roots_); }
    // The file `name` names, or std::runtime_error "<where> <what> '<name>' <problem>" (not found,
    // outside the roots, not a regular file).
    std::string require(const std::string& name, const std::string& where, const std::string& what) const;
    const std::vector<std::string>& searchDirs() const { return searchDirs_; }
    const std::vector<std::string>& roots() const { return roots_; }

private:
    std::vector<std::string> searchDirs_, roots_;
};

// True if `name` is a bare file name (no folder part): only such a name may be looked up in a
// resource group, whose own locations are the game's.
bool isBareName(const std::string& name);

}  // namespace obscura::map
