// See level_geometry.h.
#include "render/ogre_convert.h"
#include "render/level_geometry.h"

#include "map/quake_light.h"
#include "render/level_chunks.h"
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
bool isSky(const std::string& texture) {
    return texture.size() >= 3 && (texture[0] == 's' || texture[0] == 'S') && (texture[1] == 'k' || texture[1] == 'K') &&
           (texture[2] == 'y' || texture[2] == 'Y');
}

double levelSize(const map::Level& level) {
    return level.bounds.empty() ? 1.0 : length(level.bounds.max - level.bounds.min);
}

// OGRE takes a light's reach as a float range; a light that reaches nothing still needs a positive one.
constexpr double kMinLightRange = 1e-3;
}  // namespace

LevelGeometry::LevelGeometry(Ogre::SceneManager& scene, const map::Level& level, LevelMaterials& materials,
                             double chunkSize)
    : scene_(scene) {
    node_ = scene_.getRootSceneNode()->createChildSceneNode();
    buildMeshes(level, materials, chunkSize);
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

void LevelGeometry::buildMeshes(const map::Level& level, LevelMaterials& materials, double chunkSize) {
    // Lights no longer limit a chunk (level.frag reads them per pixel from the light grid).

    const std::vector<LevelChunk> chunks = buildChunks(level, chunkSize, {}, std::numeric_limits<std::size_t>::max(), isSky);

    for (const LevelChunk& chunk : chunks) {
        // Each chunk on its own node at its centre: OGRE picks a chunk's lights by the sphere around
        // its node (ManualObject radius = the farthest vertex from the node), so vertices are relative.
        auto* mo = scene_.createManualObject();
        mo->setCastShadows(!chunk.sky);  // into the sun's shadow map
        if (chunk.sky) mo->setVisibilityFlags(kSkyVisibilityFlag);
        std::map<std::string, std::vector<const ChunkPolygon*>> byMaterial;
        for (const auto& p : chunk.polygons) byMaterial[materials.resolve(p.texture)].push_back(&p);
        for (const auto& [material, polys] : byMaterial) {
            mo->begin(material, Ogre::RenderOperation::OT_TRIANGLE_LIST);
            Ogre::uint32 base = 0;
            for (const auto* poly : polys) {
                for (const auto& v : poly->vertices) {
                    mo->position(toOgre(v.position - chunk.centre));
                    mo->normal(toOgre(v.normal));
                    mo->textureCoord(static_cast<float>(v.u), static_cast<float>(v.v));
                }
                // Convex polygon, counter-clockwise from the front: a fan.
                const auto n = static_cast<Ogre::uint32>(poly->vertices.size());
                for (Ogre::uint32 i = 1; i + 1 < n; ++i) mo->triangle(base, base + i, base + i + 1);
                stats_.triangles += n - 2;
                base += n;
            }
            mo->end();
            ++stats_.batches;
        }
        node_->createChildSceneNode(toOgre(chunk.centre))->attachObject(mo);
        objects_.push_back(mo);
    }
    stats_.chunks = chunks.size();
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
