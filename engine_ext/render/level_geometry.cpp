// See level_geometry.h.
#include "render/ogre_convert.h"
#include "render/level_geometry.h"

#include "level/level_shared.h"
#include "map/quake_light.h"
#include "render/level_chunks.h"
#include "render/level_materials.h"

#include <OgreLight.h>
#include <OgreLogManager.h>
#include <OgreManualObject.h>
#include <OgreSceneManager.h>
#include <OgreSceneNode.h>

#include <cmath>
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
}

LevelGeometry::~LevelGeometry() {
    for (auto* o : objects_) scene_.destroyManualObject(o);
    for (auto* l : lights_) scene_.destroyLight(l);
    node_->removeAndDestroyAllChildren();
    scene_.destroySceneNode(node_);
}

void LevelGeometry::buildMeshes(const map::Level& level, LevelMaterials& materials, double chunkSize) {
    std::vector<LightSphere> spheres;
    for (const auto& l : level.lights) spheres.push_back({l.position, std::max(l.radius, kMinLightRange)});
    // The sun (a directional light, always in OGRE's list) takes one of the pass's lights.
    const std::size_t pointSlots = LEVEL_MAX_LIGHTS - 1;
    ChunkStats cs;
    const std::vector<LevelChunk> chunks = buildChunks(level, chunkSize, spheres, pointSlots, isSky, &cs);

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
    stats_.chunkCuts = cs.split;
    stats_.overfullChunks = cs.overfull;
    stats_.mostLightsPerChunk = cs.mostLights;
    if (cs.overfull > 0) {
        std::ostringstream os;
        os << "obscura: level: " << cs.overfull << " chunk(s) smaller than " << kMinChunkEdge << " m are still reached by more than "
           << pointSlots << " lights (at most " << cs.mostLights << "): the farthest of them do not light those faces";
        Ogre::LogManager::getSingleton().logMessage(os.str());
    }
}

void LevelGeometry::buildLights(const map::Level& level) {
    const double size = levelSize(level);
    for (const auto& l : level.lights) {
        auto* light = scene_.createLight();
        light->setType(l.spot ? Ogre::Light::LT_SPOTLIGHT : Ogre::Light::LT_POINT);
        light->setCastShadows(false);
        // The packing level.frag reads (see its uniforms): diffuse = colour x value / 200 (the
        // irradiance at full strength); attenuation = (reach, formula, map units per metre x wait,
        // the gate as a fraction of the strength); specular = (_anglescale, _falloff_exponent, spot).
        const float k = static_cast<float>(l.intensity / map::kQuakeLightUnit);
        light->setDiffuseColour(static_cast<float>(l.colour.x) * k, static_cast<float>(l.colour.y) * k,
                                static_cast<float>(l.colour.z) * k);
        const bool gated = l.formula == map::LightFormula::Inverse || l.formula == map::LightFormula::InverseSquare ||
                           l.formula == map::LightFormula::InverseSquareA;
        const double gate = gated && k != 0 ? map::kLightGate / std::fabs(k) : 0.0;
        const double reach = std::max(l.formula == map::LightFormula::Linear ? l.radius : map::lightReach(l, size), kMinLightRange);
        light->setAttenuation(static_cast<float>(reach), static_cast<float>(static_cast<int>(l.formula)),
                              static_cast<float>(l.unitsPerMetreScaled), static_cast<float>(gate));
        light->setSpecularColour(Ogre::ColourValue(static_cast<float>(l.angleScale), static_cast<float>(l.falloffExponent),
                                                   l.spot ? 1.f : 0.f, 0.f));
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

}  // namespace obscura::render
