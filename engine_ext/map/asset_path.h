// Files a level names (misc_model `model`) are confined: a level may only reach files inside its
// own folder and the game's media folders, whatever `..`, absolute paths or symlinks it uses.
// Plain C++ (std::filesystem); render/model_loader.cpp uses it before OGRE sees any path.
#pragma once

#include <string>
#include <vector>

namespace obscura::map {

struct AssetPath {
    std::string file;   // canonical path of the file found inside a root; empty if none
    std::string error;  // why the name is refused (outside every root); empty if not refused
};

// Looks for `name` as a file: as is when absolute, else relative to each of `searchDirs` in turn.
// The first regular file found is resolved (symlinks and `..`) and must lie inside one of `roots`
// (themselves resolved; missing roots are ignored), else `error` says where it led. A name that
// is no file anywhere gives neither (the caller may look a bare name up elsewhere).
AssetPath resolveAsset(const std::string& name, const std::vector<std::string>& searchDirs, const std::vector<std::string>& roots);

// The roots a level's files (misc_model meshes, decal_sign images) may resolve into: the level's
// folder, and `media/` and `../shared` of each search folder.
std::vector<std::string> levelAssetRoots(const std::string& levelPath, const std::vector<std::string>& searchDirs);

// True if `name` is a bare file name (no folder part): only such a name may be looked up in a
// resource group, whose own locations are the game's.
bool isBareName(const std::string& name);

}  // namespace obscura::map
