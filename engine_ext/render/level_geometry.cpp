// See level_geometry.h.
#include "render/ogre_convert.h"
#include "render/level_geometry.h"

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
struct ChunkKey {
    long x, y, z;
    bool sky;  // sky faces batch apart: they must not cast the sun's shadow over the whole level
    bool operator<(const ChunkKey& o) const { return std::tie(x, y, z, sky) < std::tie(o.x, o.y, o.z, o.sky); }
};

bool isSky(const std::string& texture) {
    return texture.size() >= 3 && (texture[0] == 's' || texture[0] == 'S') && (texture[1] == 'k' || texture[1] == 'K') &&
           (texture[2] == 'y' || texture[2] == 'Y');
}


// One section per material of the polygons, each a triangle fan (convex, counter-clockwise from
// the front). Returns the triangles added.
using ByMaterial = std::map<std::string, std::vector<const map::LevelPolygon*>>;
std::size_t fill(Ogre::ManualObject& mo, const ByMaterial& byMaterial) {
    std::size_t triangles = 0;
    for (const auto& [material, polys] : byMaterial) {
        mo.begin(material, Ogre::RenderOperation::OT_TRIANGLE_LIST);
        Ogre::uint32 base = 0;
        for (const auto* poly : polys) {
            for (const auto& v : poly->vertices) {
                mo.position(toOgre(v.position));
                mo.normal(toOgre(v.normal));
                mo.textureCoord(static_cast<float>(v.u), static_cast<float>(v.v));
            }
            const auto n = static_cast<Ogre::uint32>(poly->vertices.size());
            for (Ogre::uint32 i = 1; i + 1 < n; ++i) mo.triangle(base, base + i, base + i + 1);
            triangles += n - 2;
            base += n;
        }
        mo.end();
    }
    return triangles;
}

// A Quake `light` of 300 (the default) is a bright bulb; this maps it to a diffuse colour of
// about 1.5 at the light, which with the squared falloff in level.frag reads like Quake's lighting.
constexpr double kLightColourPer300 = 1.5;
}  // namespace

LevelGeometry::LevelGeometry(Ogre::SceneManager& scene, const map::Level& level, LevelMaterials& materials,
                             double chunkSize)
    : scene_(scene) {
    node_ = scene_.getRootSceneNode()->createChildSceneNode();
    buildMeshes(level, materials, chunkSize);
    buildMovers(level, materials);
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
    std::map<ChunkKey, ByMaterial> chunks;
    for (const auto& brush : level.brushes) {
        if (!brush.visible || brush.mover) continue;
        for (const auto& poly : brush.faces) {
            if (!poly.visible || poly.vertices.size() < 3) continue;
            Vec3 c;
            for (const auto& v : poly.vertices) c += v.position;
            c = c / static_cast<double>(poly.vertices.size());
            const ChunkKey key{static_cast<long>(std::floor(c.x / chunkSize)), static_cast<long>(std::floor(c.y / chunkSize)),
                               static_cast<long>(std::floor(c.z / chunkSize)), isSky(poly.texture)};
            chunks[key][materials.resolve(poly.texture)].push_back(&poly);
        }
    }

    for (const auto& [key, byMaterial] : chunks) {
        auto* mo = scene_.createManualObject();
        mo->setCastShadows(!key.sky);  // into the sun's shadow map
        if (key.sky) mo->setVisibilityFlags(kSkyVisibilityFlag);
        stats_.triangles += fill(*mo, byMaterial);
        stats_.batches += byMaterial.size();
        node_->attachObject(mo);
        objects_.push_back(mo);
    }
    stats_.chunks = chunks.size();
}

void LevelGeometry::buildMovers(const map::Level& level, LevelMaterials& materials) {
    std::map<int, ByMaterial> byMover;
    for (const auto& brush : level.brushes) {
        if (!brush.visible || !brush.mover) continue;
        for (const auto& poly : brush.faces)
            if (poly.visible && poly.vertices.size() >= 3) byMover[brush.entityIndex][materials.resolve(poly.texture)].push_back(&poly);
    }
    for (const auto& [entity, byMaterial] : byMover) {
        auto* mo = scene_.createManualObject();
        mo->setCastShadows(true);
        stats_.triangles += fill(*mo, byMaterial);
        stats_.batches += byMaterial.size();
        auto* n = node_->createChildSceneNode();
        n->attachObject(mo);
        objects_.push_back(mo);
        movers_[entity] = n;
    }
}

void LevelGeometry::setMoverOffset(int entityIndex, const Vec3& offset) {
    const auto it = movers_.find(entityIndex);
    if (it != movers_.end()) it->second->setPosition(toOgre(offset));
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
