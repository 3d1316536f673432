// See level_geometry.h.
#include "render/ogre_convert.h"
#include "render/level_geometry.h"

#include "frame/frame.h"
#include "map/quake_light.h"
#include "render/level_materials.h"
#include "render/light_grid.h"

#include <OgreGpuProgramManager.h>
#include <OgreHardwarePixelBuffer.h>
#include <OgreLight.h>
#include <OgreMaterialManager.h>
#include <OgreTechnique.h>
#include <OgreTextureManager.h>
#include <OgreLogManager.h>
#include <OgreManualObject.h>
#include <OgreSceneManager.h>
#include <OgreSceneNode.h>

#include <cmath>
#include <limits>
#include <map>
#include <sstream>

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
    const lightbake::Chart* chart = nullptr;  // a baked face's lightmap chart: its uv1
};

double levelSize(const map::Level& level) {
    return level.bounds.empty() ? 1.0 : length(level.bounds.max - level.bounds.min);
}

// OGRE takes a light's reach as a float range; a light that reaches nothing still needs a positive one.
constexpr double kMinLightRange = 1e-3;

// One section per material of the faces, each a triangle fan (convex, counter-clockwise from the
// front); a two-sided face (liquids) again, reversed and facing in. Returns the triangles added.
using ByMaterial = std::map<std::string, std::vector<Face>>;
std::size_t fill(Ogre::ManualObject& mo, const ByMaterial& byMaterial, const lightbake::Atlas* atlas = nullptr) {
    std::size_t triangles = 0;
    for (const auto& [material, faces] : byMaterial) {
        mo.begin(material, Ogre::RenderOperation::OT_TRIANGLE_LIST);
        Ogre::uint32 base = 0;
        for (const Face& f : faces) {
            for (int side = 0; side < (f.twoSided ? 2 : 1); ++side) {
                const float flip = side == 0 ? 1.0f : -1.0f;
                for (const auto& v : f.poly->vertices) {
                    mo.position(toOgre(v.position));
                    mo.normal(toOgre(v.normal) * flip);
                    mo.textureCoord(static_cast<float>(v.u), static_cast<float>(v.v));
                    if (f.chart) {  // a baked material's section: every face in it has a chart
                        double u, w;
                        atlas->atlasCoord(*f.chart, v.position, u, w);
                        mo.textureCoord(static_cast<float>(u / atlas->width), static_cast<float>(w / atlas->height));
                    }
                }
                const auto n = static_cast<Ogre::uint32>(f.poly->vertices.size());
                for (Ogre::uint32 i = 1; i + 1 < n; ++i) {
                    if (side == 0) mo.triangle(base, base + i, base + i + 1);
                    else mo.triangle(base, base + i + 1, base + i);
                }
                triangles += n - 2;
                base += n;
            }
        }
        mo.end();
    }
    return triangles;
}
}  // namespace

LevelGeometry::LevelGeometry(Ogre::SceneManager& scene, const map::Level& level, LevelMaterials& materials,
                             const lightbake::Atlas* lightmaps, double chunkSize)
    : scene_(scene) {
    node_ = scene_.getRootSceneNode()->createChildSceneNode();
    buildMeshes(level, materials, lightmaps, chunkSize);
    buildMovers(level, materials);
    buildLights(level);
    buildLightGrid(level);
}

LevelGeometry::~LevelGeometry() {
    for (auto* o : objects_) scene_.destroyManualObject(o);
    for (auto* l : lights_) scene_.destroyLight(l);
    if (lightTexture_) Ogre::TextureManager::getSingleton().remove(lightTexture_);
    node_->removeAndDestroyAllChildren();
    scene_.destroySceneNode(node_);
}

void LevelGeometry::buildMeshes(const map::Level& level, LevelMaterials& materials, const lightbake::Atlas* lightmaps,
                                double chunkSize) {
    // The baked faces' charts by (brush, face).
    std::map<std::pair<int, int>, const lightbake::Chart*> charts;
    if (lightmaps)
        for (const auto& c : lightmaps->charts) charts[{c.ref.brush, c.ref.face}] = &c;
    // chunk -> material -> polygons
    std::map<ChunkKey, ByMaterial> chunks;
    for (std::size_t b = 0; b < level.brushes.size(); ++b) {
        const auto& brush = level.brushes[b];
        if (!brush.visible || brush.mover) continue;  // movers: their own nodes (buildMovers)
        const bool liquid = brush.liquid != map::LiquidKind::None;
        const bool translucent = liquid && brush.liquidAlpha < 1.0;
        for (std::size_t f = 0; f < brush.faces.size(); ++f) {
            const auto& poly = brush.faces[f];
            if (!poly.visible || poly.vertices.size() < 3) continue;
            Vec3 c;
            for (const auto& v : poly.vertices) c += v.position;
            c = c / static_cast<double>(poly.vertices.size());
            const Batch batch = translucent ? Batch::TranslucentLiquid : poly.sky ? Batch::Sky : Batch::Solid;
            const ChunkKey key{static_cast<long>(std::floor(c.x / chunkSize)), static_cast<long>(std::floor(c.y / chunkSize)),
                               static_cast<long>(std::floor(c.z / chunkSize)), batch};
            const auto chart = charts.find({static_cast<int>(b), static_cast<int>(f)});
            if (chart != charts.end()) {
                chunks[key][materials.resolveBaked(poly.texture)].push_back({&poly, false, chart->second});
                ++stats_.bakedFaces;
                continue;
            }
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
        stats_.triangles += fill(*mo, byMaterial, lightmaps);
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
            if (poly.visible && poly.vertices.size() >= 3) byMover[brush.entityIndex][materials.resolve(poly.texture, poly.sky)].push_back({&poly, false});
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
    const double size = levelSize(level);
    for (const auto& l : level.lights) {
        auto* light = scene_.createLight();
        light->setType(l.spot ? Ogre::Light::LT_SPOTLIGHT : Ogre::Light::LT_POINT);
        light->setCastShadows(false);
        // OGRE's copy of the map's lights is for the smoke (its lamps: diffuse and range); the
        // level's surfaces read them from the light grid (buildLightGrid).
        const float k = static_cast<float>(l.intensity / map::kQuakeLightUnit);
        light->setDiffuseColour(static_cast<float>(l.colour.x) * k, static_cast<float>(l.colour.y) * k,
                                static_cast<float>(l.colour.z) * k);
        light->setSpecularColour(Ogre::ColourValue::Black);
        light->setAttenuation(static_cast<float>(std::max(map::lightReach(l, size), kMinLightRange)), 1.0f, 0.0f, 0.0f);
        auto* n = node_->createChildSceneNode(toOgre(l.position));
        if (l.spot) {
            // OGRE's cone angles are full angles; level.frag reads the cosines of their halves.
            light->setSpotlightRange(Ogre::Radian(static_cast<float>(2 * std::acos(l.spotCosInner))),
                                     Ogre::Radian(static_cast<float>(2 * std::acos(l.spotCosOuter))), 1.0f);
            n->setDirection(toOgre(l.spotDirection), Ogre::Node::TS_WORLD);
        }
        n->attachObject(light);
        lights_.push_back(light);
    }
    stats_.lights = lights_.size();
}

void LevelGeometry::buildLightGrid(const map::Level& level) {
    const LightGrid grid = render::buildLightGrid(level);
    static int serial = 0;  // a texture name of its own per level loaded
    lightTexture_ = Ogre::TextureManager::getSingleton().createManual(
        "Obscura/LevelLights/" + std::to_string(serial++), Ogre::RGN_DEFAULT, Ogre::TEX_TYPE_2D, kLightGridWidth,
        static_cast<Ogre::uint>(grid.rows()), 0, Ogre::PF_FLOAT32_RGBA, Ogre::TU_STATIC_WRITE_ONLY);
    lightTexture_->getBuffer()->blitFromMemory(Ogre::PixelBox(kLightGridWidth, static_cast<Ogre::uint32>(grid.rows()), 1,
                                                              Ogre::PF_FLOAT32_RGBA, const_cast<float*>(grid.texels.data())));
    // Every material with the level pass's light unit (level/*, generated, the G-buffer fallback).
    auto it = Ogre::MaterialManager::getSingleton().getResourceIterator();
    while (it.hasMoreElements()) {
        auto* material = static_cast<Ogre::Material*>(it.getNext().get());
        for (auto* tech : material->getTechniques())
            for (auto* pass : tech->getPasses())
                if (auto* unit = pass->getTextureUnitState("levelLights")) unit->setTexture(lightTexture_);
    }
    auto& gpm = Ogre::GpuProgramManager::getSingleton();
    const auto& all = gpm.getAvailableSharedParameters();
    if (all.find("ObscuraLevelLights") == all.end())
        throw std::runtime_error("shared_params ObscuraLevelLights is missing (media/materials/level.program)");
    Ogre::GpuSharedParametersPtr p = gpm.getSharedParameters("ObscuraLevelLights");
    p->setNamedConstant("lightGridOrigin", Ogre::Vector4(static_cast<float>(grid.origin.x), static_cast<float>(grid.origin.y),
                                                         static_cast<float>(grid.origin.z), static_cast<float>(grid.cell)));
    p->setNamedConstant("lightGridSize", Ogre::Vector4(static_cast<float>(grid.nx), static_cast<float>(grid.ny),
                                                       static_cast<float>(grid.nz), static_cast<float>(kLightGridWidth)));
    p->setNamedConstant("lightGridBases", Ogre::Vector4(static_cast<float>(grid.headerBase), static_cast<float>(grid.indexBase), 0, 0));
    stats_.gridCell = grid.cell;
    stats_.mostLightsPerCell = grid.mostInACell;
}

}  // namespace obscura::render
