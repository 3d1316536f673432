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

// A relative `model` path is looked for in each of `searchDirs` in turn (the game passes the .map
// file's folder, the data folder and the working directory), an absolute one as is; the file found
// must resolve (symlinks and `..` first) inside the level's folder, or `media/` or `../shared` of a
// search folder (modelRoots), else it is an error naming the level, the entity's line and where the
// path led, and its folder never becomes a resource location. A bare name that is no file is
// looked up in the resource group. `levelPath` names the level in errors.
// The model's world transform: translate(origin) * rotateY(yaw) * scale.
Ogre::Affine3 modelTransform(const map::LevelModel& model);
// Every submesh's triangles, transformed (shared by the game's colliders and tools/aoref).
TriangleMesh meshTriangles(const Ogre::Mesh& mesh, const Ogre::Affine3& transform);

// The folders a level's models may come from (see above).
std::vector<std::string> modelRoots(const std::string& levelPath, const std::vector<std::string>& searchDirs);

TriangleMesh placeModel(Ogre::SceneManager& scene, const map::LevelModel& model, const std::string& levelPath,
                        const std::vector<std::string>& searchDirs, const std::string& group, LevelMaterials& materials);

}  // namespace obscura::render
