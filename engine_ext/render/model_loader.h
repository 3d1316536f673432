// misc_model: places an OGRE .mesh in the scene and returns its triangles in world space for a
// static triangle-mesh collider. Submesh materials that do not exist get generated fallbacks
// (as unknown level textures do); a missing mesh file is a load error.
#pragma once

#include "map/level.h"
#include "core/triangle_mesh.h"

#include <string>
#include <vector>

#include <OgreMatrix4.h>

namespace Ogre {
class Mesh;
class SceneManager;
}  // namespace Ogre

namespace obscura::render {

class LevelMaterials;

// The model's world transform: translate(origin) * rotateY(yaw) * scale.
Ogre::Affine3 modelTransform(const map::LevelModel& model);
// Every submesh's triangles, transformed (shared by the game's colliders and tools/aoref).
TriangleMesh meshTriangles(const Ogre::Mesh& mesh, const Ogre::Affine3& transform);

// The `model` file is found by map::LevelFiles (the one confined lookup: the level's folder and the
// media folders, regular files only), else it is an error naming the level, the entity's line and
// where the path led, and its folder never becomes a resource location. A bare name that is no file
// is looked up in the resource group. `levelPath` names the level in errors.
TriangleMesh placeModel(Ogre::SceneManager& scene, const map::LevelModel& model, const std::string& levelPath,
                        const std::vector<std::string>& searchDirs, const std::string& group, LevelMaterials& materials);

}  // namespace obscura::render
