// See meshuggah.h.
#include "signs/meshuggah.h"

#include "frame/frame.h"
#include "signs/sign_render.h"

#include <Ogre.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace obscura::signs {

namespace {
Ogre::Vector3 ogre(const Vec3& v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
// Quads a ray is cut into along its length: the vertex shader caps a strip's width by its distance
// to the eye (meshuggah.vert) at the cuts, so a ray passing by the camera stays thin there.
constexpr int kSegments = 16;
}  // namespace

Meshuggah::Meshuggah(Ogre::SceneManager& scene, const std::vector<SignSpec>& specs, const std::vector<SignMask>& masks)
    : scene_(scene), specs_(specs), masks_(masks), rayCounts_(specs.size(), 0), spacing_(specs.size(), 0) {
    if (specs_.empty()) return;
    Ogre::MaterialPtr base = Ogre::MaterialManager::getSingleton().getByName("Obscura/Signs/Meshuggah");
    if (!base) throw std::runtime_error("material Obscura/Signs/Meshuggah (media/signs/meshuggah.material) is missing");
    for (std::size_t i = 0; i < specs_.size(); ++i) {
        Ogre::MaterialPtr mat = base->clone("Obscura/Signs/Meshuggah" + std::to_string(i));
        mat->load();
        materials_.push_back(mat);
        auto* rays = scene_.createManualObject("Obscura/Signs/MeshuggahRays" + std::to_string(i));
        rays->setDynamic(true);  // rebuilt (beginUpdate) when the holes change
        rays->setCastShadows(false);
        rays->setRenderQueueGroup(frame::kEffectsQueue);  // into `lit`, after the lighting quad
        // Kept out of the lamps' shadow maps, as the plates are; hidden until update() shows them
        // (the AO's height map is rendered at load from the scene).
        rays->setVisibilityFlags(kPlateVisibilityFlag);
        rays->setVisible(false);
        Ogre::SceneNode* node = scene_.getRootSceneNode()->createChildSceneNode();
        node->attachObject(rays);
        rays_.push_back(rays);
        nodes_.push_back(node);
        build(i, {});
        Ogre::LogManager::getSingleton().logMessage("signs: meshuggah: " + specs_[i].where + ": " + std::to_string(rayCounts_[i]) +
                                                    " rays, a texel every " + std::to_string(spacing_[i] * 1000) + " mm");
    }
}

Meshuggah::~Meshuggah() {
    for (std::size_t i = 0; i < rays_.size(); ++i) {
        nodes_[i]->detachAllObjects();
        scene_.destroyManualObject(rays_[i]);
        scene_.destroySceneNode(nodes_[i]);
        Ogre::MaterialManager::getSingleton().remove(materials_[i]);
    }
}

void Meshuggah::setHoles(std::size_t i, const std::vector<Hole>& holes) {
    if (i < rays_.size()) build(i, holes);
}

// A ray is kSegments quads end to end from the plate to the range: each cut's point twice, across
// = -1 and +1. The vertex shader moves each sideways by its half width, perpendicular to the ray
// and to the eye (and narrows it near the eye: the cuts let it do that along the ray).
//   position  the point on the ray's axis (world; the node is the root's identity)
//   normal    the ray's direction
//   uv0       (across -1 | +1, distance from the lamp)
//   uv1       (coverage 0..1: the 8-bit value / 255, half width at this end)
void Meshuggah::build(std::size_t i, const std::vector<Hole>& holes) {
    const SignSpec& s = specs_[i];
    double spacing = 0;
    const std::vector<MeshuggahRay> rays = meshuggahRays(s, masks_[i], holes, spacing);
    rayCounts_[i] = rays.size();
    spacing_[i] = spacing;
    Ogre::ManualObject* mo = rays_[i];
    if (rays.empty()) {
        mo->clear();
        return;
    }
    if (mo->getSections().empty()) {
        mo->estimateVertexCount(rays.size() * 2 * (kSegments + 1));
        mo->estimateIndexCount(rays.size() * 6 * kSegments);
        mo->begin(materials_[i]->getName(), Ogre::RenderOperation::OT_TRIANGLE_LIST);
    } else {
        mo->beginUpdate(0);
    }
    Ogre::uint32 base = 0;
    for (const MeshuggahRay& r : rays) {
        const double a = length(r.start - s.lamp);  // the lamp's distance at the plate
        const double coverage = r.coverage / 255.0;
        for (int k = 0; k <= kSegments; ++k) {
            const double t = r.length * k / kSegments, dist = a + t;
            for (int side = -1; side <= 1; side += 2) {
                mo->position(ogre(r.start + r.direction * t));
                mo->normal(ogre(r.direction));
                mo->textureCoord(static_cast<float>(side), static_cast<float>(dist));
                // The texel's cone: spacing at the plate, growing as the distance from the lamp.
                mo->textureCoord(static_cast<float>(coverage), static_cast<float>(spacing * dist / a));
            }
            if (k > 0) mo->quad(base - 2, base - 1, base + 1, base);
            base += 2;
        }
    }
    mo->end();
}

void Meshuggah::update(bool on, const std::vector<std::size_t>& chosen, const std::vector<Ogre::TexturePtr>& shadowMaps,
                       const std::vector<Ogre::Matrix4>& shadowMatrices, float haze) {
    for (std::size_t i = 0; i < rays_.size(); ++i) {
        const auto it = std::find(chosen.begin(), chosen.end(), i);
        const bool shown = on && haze > 0 && it != chosen.end() && rayCounts_[i] > 0;
        rays_[i]->setVisible(shown);
        if (!shown) continue;
        const std::size_t slot = static_cast<std::size_t>(it - chosen.begin());
        const SignSpec& s = specs_[i];
        Ogre::Pass* pass = materials_[i]->getTechnique(0)->getPass(0);
        if (slot < shadowMaps.size()) pass->getTextureUnitState("rayShadow")->setTexture(shadowMaps[slot]);
        const Ogre::GpuProgramParametersSharedPtr fp = pass->getFragmentProgramParameters();
        const Ogre::Vector3 lamp = ogre(s.lamp);
        fp->setNamedConstant("rayLamp", Ogre::Vector4(lamp.x, lamp.y, lamp.z, static_cast<float>(s.lightRadius)));
        const Ogre::Vector3 c = ogre(s.lightColour * s.intensity);
        fp->setNamedConstant("rayColour", Ogre::Vector4(c.x, c.y, c.z, static_cast<float>(s.range)));
        fp->setNamedConstant("rayHaze", haze);
        fp->setNamedConstant("rayShadowMatrix", slot < shadowMatrices.size() ? shadowMatrices[slot] : Ogre::Matrix4::IDENTITY);
        fp->setNamedConstant("rayShadowOn", slot < shadowMaps.size() ? 1.0f : 0.0f);
    }
}

}  // namespace obscura::signs
