// Renders the simulation's dynamic props (crates, barrels) and grenades as textured boxes,
// cylinders and spheres, one entity per body, moved each frame from poses the game pushes in.
// Owns what it creates. The unit meshes are built once (procedurally) and shared.
#pragma once

#include "core/vec3.h"

#include <string>
#include <vector>

namespace Ogre {
class Entity;
class SceneManager;
class SceneNode;
}  // namespace Ogre

namespace obscura::render {

class LevelMaterials;

struct PropPose {
    enum class Shape { Box, Cylinder, Sphere };
    Vec3 position;
    double qx = 0, qy = 0, qz = 0, qw = 1;
    Vec3 halfExtents{0.5, 0.5, 0.5};  // cylinder: radius x, half height y; sphere: radius x
    Shape shape = Shape::Box;
    std::string material;  // a level texture name ("crate", "barrel", "metal"...)
};

// The shared unit meshes: a cube -1..1, a Y-axis cylinder of radius 1 and half height 1, a sphere
// of radius 1 (all with normals and UVs). Built on first use.
const std::string& unitMesh(PropPose::Shape shape);

class PropView {
public:
    PropView(Ogre::SceneManager& scene, LevelMaterials& materials);
    ~PropView();
    PropView(const PropView&) = delete;
    PropView& operator=(const PropView&) = delete;

    void update(const std::vector<PropPose>& poses);

private:
    Ogre::SceneManager& scene_;
    LevelMaterials& materials_;
    struct Item {
        Ogre::SceneNode* node = nullptr;
        Ogre::Entity* entity = nullptr;
        PropPose::Shape shape;
        std::string material;
    };
    std::vector<Item> items_;
};

}  // namespace obscura::render
