// See prop_view.h.
#include "render/prop_view.h"

#include "render/level_materials.h"

#include <Ogre.h>

namespace obscura::render {

namespace {
const char* const kBoxMesh = "Obscura/PropBox";

// A unit cube (-1..1) with per-face normals and UVs, built once.
void ensureBoxMesh(const std::string& material) {
    if (Ogre::MeshManager::getSingleton().resourceExists(kBoxMesh, Ogre::RGN_DEFAULT)) return;
    Ogre::ManualObject mo("PropBoxBuilder");
    mo.begin(material, Ogre::RenderOperation::OT_TRIANGLE_LIST);
    const Ogre::Vector3 normals[6] = {Ogre::Vector3::UNIT_X, Ogre::Vector3::NEGATIVE_UNIT_X, Ogre::Vector3::UNIT_Y,
                                      Ogre::Vector3::NEGATIVE_UNIT_Y, Ogre::Vector3::UNIT_Z, Ogre::Vector3::NEGATIVE_UNIT_Z};
    Ogre::uint32 base = 0;
    for (const auto& n : normals) {
        // Two tangents completing a right-handed frame, so the face winds counter-clockwise from outside.
        const Ogre::Vector3 t = n.perpendicular();
        const Ogre::Vector3 b = n.crossProduct(t);
        const Ogre::Vector3 corners[4] = {n - t - b, n + t - b, n + t + b, n - t + b};
        const float uv[4][2] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
        for (int i = 0; i < 4; ++i) {
            mo.position(corners[i]);
            mo.normal(n);
            mo.textureCoord(uv[i][0], uv[i][1]);
        }
        mo.quad(base, base + 1, base + 2, base + 3);
        base += 4;
    }
    mo.end();
    mo.convertToMesh(kBoxMesh);
}
}  // namespace

PropView::PropView(Ogre::SceneManager& scene, LevelMaterials& materials)
    : scene_(scene), material_(materials.resolve("crate")) {
    ensureBoxMesh(material_);
}

PropView::~PropView() {
    for (auto* e : entities_) scene_.destroyEntity(e);
    for (auto* n : nodes_) scene_.destroySceneNode(n);
}

void PropView::update(const std::vector<PropPose>& poses) {
    while (entities_.size() < poses.size()) {
        auto* e = scene_.createEntity(kBoxMesh);
        auto* n = scene_.getRootSceneNode()->createChildSceneNode();
        n->attachObject(e);
        entities_.push_back(e);
        nodes_.push_back(n);
    }
    for (size_t i = 0; i < nodes_.size(); ++i) {
        const bool used = i < poses.size();
        nodes_[i]->setVisible(used);
        if (!used) continue;
        const auto& p = poses[i];
        nodes_[i]->setPosition(static_cast<float>(p.position.x), static_cast<float>(p.position.y), static_cast<float>(p.position.z));
        nodes_[i]->setOrientation(static_cast<float>(p.qw), static_cast<float>(p.qx), static_cast<float>(p.qy), static_cast<float>(p.qz));
        nodes_[i]->setScale(static_cast<float>(p.halfExtents.x), static_cast<float>(p.halfExtents.y), static_cast<float>(p.halfExtents.z));
    }
}

}  // namespace obscura::render
