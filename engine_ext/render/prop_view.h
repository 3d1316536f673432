// Renders the simulation's dynamic props (crates) as textured boxes, one entity per body,
// moved each frame from poses the game pushes in. Owns what it creates.
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
    Vec3 position;
    double qx = 0, qy = 0, qz = 0, qw = 1;
    Vec3 halfExtents{0.5, 0.5, 0.5};
};

class PropView {
public:
    PropView(Ogre::SceneManager& scene, LevelMaterials& materials);
    ~PropView();
    PropView(const PropView&) = delete;
    PropView& operator=(const PropView&) = delete;

    void update(const std::vector<PropPose>& poses);

private:
    Ogre::SceneManager& scene_;
    std::string material_;
    std::vector<Ogre::SceneNode*> nodes_;
    std::vector<Ogre::Entity*> entities_;
};

}  // namespace obscura::render
