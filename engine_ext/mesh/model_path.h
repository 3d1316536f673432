// Where a misc_model's mesh file is: the lookup the game and tools/aoref share, without OGRE.
#pragma once

#include <string>
#include <vector>

namespace obscura::mesh {

// An absolute `model` path is taken as is; a relative one is tried in each of `searchDirs` in
// turn (the game passes the .map file's folder, the data folder and the working directory).
// Returns the first that is a regular file, canonical, or "" when none is. (The renderer's extra
// fallback, a bare name looked up in an OGRE resource group, stays with the renderer.)
std::string findModelFile(const std::string& model, const std::vector<std::string>& searchDirs);

}  // namespace obscura::mesh
