// Turns a compiled level (map::Level) into OGRE geometry: visible brush faces batched per
// material inside spatial chunks (one ManualObject per chunk, one section per material, each on its
// own scene node at the chunk's centre), so a big map draws in few batches yet still frustum-culls.
// Faces the light bake charted (engine_ext/lightbake) carry the lightmap's uv (uv1) and a baked
// material (LevelMaterials::resolveBaked); the rest (movers, liquids) read the map's lights from a
// float texture with a world grid of which lights reach each cell (light_grid.h), per pixel in
// level.frag: no light cap per batch. Plus an OGRE point light or spotlight per map light, for the smoke.
// Liquid faces are two-sided (each also drawn facing in); translucent ones (alpha < 1) are
// chunked apart, in frame::kLiquidQueue, casting no shadow (shaders/level/liquid.frag).
// RAII: everything created here is destroyed with the object.
#pragma once

#include "lightbake/lightmap_atlas.h"
#include "map/level.h"

#include <OgreTexture.h>

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
    std::size_t triangles = 0;     // liquids' back faces included
    std::size_t liquidBatches = 0;  // chunks of translucent liquid (frame::kLiquidQueue)
    std::size_t lights = 0;
    std::size_t bakedFaces = 0;         // faces drawn from the lightmaps
    double gridCell = 0;                // the light grid's cell edge, metres (light_grid.h)
    std::size_t mostLightsPerCell = 0;  // the most lights listed for one cell
};

// Visibility flag of the sky's batches (all other objects keep OGRE's default, every bit set): views
// that must not see the sky, such as the AO height map, mask it out.
constexpr unsigned kSkyVisibilityFlag = 1u << 30;
// Visibility flag of translucent liquids' batches: the AO height map leaves them out too (the sky
// shows through water).
constexpr unsigned kLiquidVisibilityFlag = 1u << 29;

class LevelGeometry {
public:
    // chunkSize: metres per chunk edge. 16 m keeps a room or two per chunk: big enough that
    // e3m4 draws in a few hundred batches, small enough that culling works and few chunks need a cut.
    // `lightmaps`: the bake's atlas (its charts' faces drawn baked), or null for none.
    LevelGeometry(Ogre::SceneManager& scene, const map::Level& level, LevelMaterials& materials,
                  const lightbake::Atlas* lightmaps = nullptr, double chunkSize = 16.0);
    ~LevelGeometry();
    LevelGeometry(const LevelGeometry&) = delete;
    LevelGeometry& operator=(const LevelGeometry&) = delete;

    const LevelGeometryStats& stats() const { return stats_; }
    // Moving brush entities (map::LevelBrush::mover) are not in the static chunks: each has its
    // own object on its own node, placed here at its offset from where the level built it.
    void setMoverOffset(int entityIndex, const Vec3& offset);
    std::size_t moverCount() const { return movers_.size(); }

private:
    void buildMeshes(const map::Level& level, LevelMaterials& materials, const lightbake::Atlas* lightmaps, double chunkSize);
    void buildMovers(const map::Level& level, LevelMaterials& materials);
    void buildLights(const map::Level& level);
    void buildLightGrid(const map::Level& level);

    Ogre::SceneManager& scene_;
    Ogre::SceneNode* node_ = nullptr;
    std::vector<Ogre::ManualObject*> objects_;
    std::vector<Ogre::Light*> lights_;
    Ogre::TexturePtr lightTexture_;
    std::map<int, Ogre::SceneNode*> movers_;  // by entity index
    LevelGeometryStats stats_;
};

}  // namespace obscura::render
