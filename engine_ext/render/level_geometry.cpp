// See level_geometry.h.
#include "render/ogre_convert.h"
#include "render/level_geometry.h"

#include "frame/frame.h"
#include "render/level_materials.h"

#include <OgreLight.h>
#include <OgreManualObject.h>
#include <OgreSceneManager.h>
#include <OgreSceneNode.h>

#include <cmath>
#include <map>
#include <tuple>

namespace obscura::render {

namespace {
// How a chunk's faces are drawn: sky faces batch apart (they must not cast the sun's shadow over
// the whole level); translucent liquids too (their own render queue after lighting, no shadow).
enum class Batch { Solid, Sky, TranslucentLiquid };

struct ChunkKey {
    long x, y, z;
    Batch batch;
    bool operator<(const ChunkKey& o) const { return std::tie(x, y, z, batch) < std::tie(o.x, o.y, o.z, o.batch); }
};

struct Face {
    const map::LevelPolygon* poly;
    bool twoSided;  // liquids: drawn again facing in, so they show from below and from inside
};


// A Quake `light` of 300 (the default) is a bright bulb; this maps it to a diffuse colour of
// about 1.5 at the light, which with the squared falloff in level.frag reads like Quake's lighting.
constexpr double kLightColourPer300 = 1.5;
}  // namespace

LevelGeometry::LevelGeometry(Ogre::SceneManager& scene, const map::Level& level, LevelMaterials& materials,
                             double chunkSize)
    : scene_(scene) {
    node_ = scene_.getRootSceneNode()->createChildSceneNode();
    buildMeshes(level, materials, chunkSize);
    buildLights(level);
}

LevelGeometry::~LevelGeometry() {
    for (auto* o : objects_) scene_.destroyManualObject(o);
    for (auto* l : lights_) scene_.destroyLight(l);
    node_->removeAndDestroyAllChildren();
    scene_.destroySceneNode(node_);
}

void LevelGeometry::buildMeshes(const map::Level& level, LevelMaterials& materials, double chunkSize) {
    // chunk -> material -> polygons
    std::map<ChunkKey, std::map<std::string, std::vector<Face>>> chunks;
    for (const auto& brush : level.brushes) {
        if (!brush.visible) continue;
        const bool liquid = brush.liquid != map::LiquidKind::None;
        const bool translucent = liquid && brush.liquidAlpha < 1.0;
        for (const auto& poly : brush.faces) {
            if (!poly.visible || poly.vertices.size() < 3) continue;
            Vec3 c;
            for (const auto& v : poly.vertices) c += v.position;
            c = c / static_cast<double>(poly.vertices.size());
            const Batch batch = translucent ? Batch::TranslucentLiquid : poly.sky ? Batch::Sky : Batch::Solid;
            const ChunkKey key{static_cast<long>(std::floor(c.x / chunkSize)), static_cast<long>(std::floor(c.y / chunkSize)),
                               static_cast<long>(std::floor(c.z / chunkSize)), batch};
            const std::string& material =
                liquid ? materials.resolveLiquid(poly.texture, brush.liquid, brush.liquidAlpha) : materials.resolve(poly.texture, poly.sky);
            chunks[key][material].push_back({&poly, liquid});
        }
    }

    for (const auto& [key, byMaterial] : chunks) {
        auto* mo = scene_.createManualObject();
        mo->setCastShadows(key.batch == Batch::Solid);  // into the sun's shadow map
        if (key.batch == Batch::Sky) mo->setVisibilityFlags(kSkyVisibilityFlag);
        if (key.batch == Batch::TranslucentLiquid) {
            mo->setRenderQueueGroup(frame::kLiquidQueue);  // forward, after lighting (frame.compositor)
            mo->setVisibilityFlags(kLiquidVisibilityFlag);
            ++stats_.liquidBatches;
        }
        for (const auto& [material, faces] : byMaterial) {
            mo->begin(material, Ogre::RenderOperation::OT_TRIANGLE_LIST);
            Ogre::uint32 base = 0;
            for (const Face& f : faces) {
                for (int side = 0; side < (f.twoSided ? 2 : 1); ++side) {
                    const float flip = side == 0 ? 1.0f : -1.0f;
                    for (const auto& v : f.poly->vertices) {
                        mo->position(toOgre(v.position));
                        mo->normal(toOgre(v.normal) * flip);
                        mo->textureCoord(static_cast<float>(v.u), static_cast<float>(v.v));
                    }
                    // Convex polygon, counter-clockwise from the front: a fan (the back: reversed).
                    const auto n = static_cast<Ogre::uint32>(f.poly->vertices.size());
                    for (Ogre::uint32 i = 1; i + 1 < n; ++i) {
                        if (side == 0) mo->triangle(base, base + i, base + i + 1);
                        else mo->triangle(base, base + i + 1, base + i);
                    }
                    stats_.triangles += n - 2;
                    base += n;
                }
            }
            mo->end();
            ++stats_.batches;
        }
        node_->attachObject(mo);
        objects_.push_back(mo);
    }
    stats_.chunks = chunks.size();
}

void LevelGeometry::buildLights(const map::Level& level) {
    for (const auto& l : level.lights) {
        auto* light = scene_.createLight();
        light->setType(Ogre::Light::LT_POINT);
        light->setCastShadows(false);
        const float k = static_cast<float>(l.intensity / 300.0 * kLightColourPer300);
        light->setDiffuseColour(static_cast<float>(l.colour.x) * k, static_cast<float>(l.colour.y) * k,
                                static_cast<float>(l.colour.z) * k);
        light->setSpecularColour(Ogre::ColourValue::Black);
        const float range = static_cast<float>(std::max(l.radius, 1.0));
        light->setAttenuation(range, 1.0f, 0.0f, 0.0f);
        auto* n = node_->createChildSceneNode(toOgre(l.position));
        n->attachObject(light);
        lights_.push_back(light);
    }
    stats_.lights = lights_.size();
}

}  // namespace obscura::render
