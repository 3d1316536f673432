// misc_model: places an OGRE .mesh in the scene and returns its triangles in world space for a
// static triangle-mesh collider. Submesh materials that do not exist get generated fallbacks
// (as unknown level textures do); a missing mesh file is a load error.
#pragma once

#include "map/level.h"
#include "core/triangle_mesh.h"

#include <string>

namespace Ogre { class SceneManager; }

namespace obscura::render {

class LevelMaterials;

// `levelPath` resolves a relative `model` path (relative to the .map file's folder, then to the
// working directory); a bare name is looked up in the resource group.
TriangleMesh placeModel(Ogre::SceneManager& scene, const map::LevelModel& model, const std::string& levelPath,
                             const std::string& group, LevelMaterials& materials);

}  // namespace obscura::render
