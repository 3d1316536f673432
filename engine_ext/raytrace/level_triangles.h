// A level's triangles as the game renders them, for the ray-traced references: the visible,
// non-sky brush faces and the misc_model meshes placed exactly as the game places them.
#pragma once

#include "core/triangle_mesh.h"
#include "map/level.h"

#include <string>
#include <vector>

namespace obscura {

// Visible, non-sky brush faces as one mesh (fences are solid here: no alpha; movers at rest).
std::vector<TriangleMesh> levelTriangles(const map::Level& level);

// Appends each misc_model's mesh, found in `searchDirs` (the level's folder, the data folder, ...);
// throws std::runtime_error naming the level and the mesh that is not found. `logPrefix` (e.g.
// "aoref"): a line per model with its bounds on stderr; empty for none.
void addModelTriangles(const map::Level& level, const std::vector<std::string>& searchDirs,
                       std::vector<TriangleMesh>& out, const std::string& logPrefix = "");

}  // namespace obscura
