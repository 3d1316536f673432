// Turns a compiled level (map::Level) into OGRE geometry: visible brush faces batched per
// material inside spatial chunks (one ManualObject per chunk, one section per material), so a
// big map draws in few batches yet still frustum-culls; plus an OGRE point light per map light.
// RAII: everything created here is destroyed with the object.
#pragma once

#include "map/level.h"

#include <cstddef>
#include <map>
#include <vector>

namespace Ogre {
class Light;
class ManualObject;
class SceneManager;
class SceneNode;
}  // namespace Ogre

namespace obscura::render {

class LevelMaterials;

struct LevelGeometryStats {
    std::size_t chunks = 0;
    std::size_t batches = 0;  // ManualObject sections = draw calls before culling
    std::size_t triangles = 0;
    std::size_t lights = 0;
};

// Visibility flag of the sky's batches (all other objects keep OGRE's default, every bit set): views
// that must not see the sky, such as the AO height map, mask it out.
constexpr unsigned kSkyVisibilityFlag = 1u << 30;

class LevelGeometry {
public:
    // chunkSize: metres per chunk edge. 16 m keeps a room or two per chunk: big enough that
    // e3m4 draws in a few hundred batches, small enough that culling and the 8-light limit work.
    LevelGeometry(Ogre::SceneManager& scene, const map::Level& level, LevelMaterials& materials,
                  double chunkSize = 16.0);
    ~LevelGeometry();
    LevelGeometry(const LevelGeometry&) = delete;
    LevelGeometry& operator=(const LevelGeometry&) = delete;

    const LevelGeometryStats& stats() const { return stats_; }
    // Moving brush entities (map::LevelBrush::mover) are not in the static chunks: each has its
    // own object on its own node, placed here at its offset from where the level built it.
    void setMoverOffset(int entityIndex, const Vec3& offset);
    std::size_t moverCount() const { return movers_.size(); }

private:
    void buildMeshes(const map::Level& level, LevelMaterials& materials, double chunkSize);
    void buildMovers(const map::Level& level, LevelMaterials& materials);
    void buildLights(const map::Level& level);

    Ogre::SceneManager& scene_;
    Ogre::SceneNode* node_ = nullptr;
    std::vector<Ogre::ManualObject*> objects_;
    std::vector<Ogre::Light*> lights_;
    std::map<int, Ogre::SceneNode*> movers_;  // by entity index
    LevelGeometryStats stats_;
};

}  // namespace obscura::render
