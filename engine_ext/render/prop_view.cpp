// See prop_view.h.
#include "render/prop_view.h"

#include "render/level_materials.h"

#include <Ogre.h>

namespace obscura::render {

namespace {
// Tessellation of the round meshes: 24 segments keep a 0.3 m barrel's outline smooth at 1 m.
constexpr int kSegments = 24;
constexpr float kPi = 3.14159265358979f;

// Any material works for building; entities get theirs set per use.
const char* const kBuildMaterial = "Obscura/Level";

void buildBox(Ogre::ManualObject& mo) {
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
}

void buildCylinder(Ogre::ManualObject& mo) {
    Ogre::uint32 base = 0;
    for (int i = 0; i <= kSegments; ++i) {  // the side: a strip, u around, v down
        const float a = 2 * kPi * static_cast<float>(i) / kSegments;
        const Ogre::Vector3 n(std::cos(a), 0, -std::sin(a));
        for (float y : {1.0f, -1.0f}) {
            mo.position(n.x, y, n.z);
            mo.normal(n);
            mo.textureCoord(static_cast<float>(i) / kSegments, y > 0 ? 0.0f : 1.0f);
        }
    }
    for (int i = 0; i < kSegments; ++i) {
        const Ogre::uint32 a = base + 2 * i;
        mo.quad(a, a + 1, a + 3, a + 2);
    }
    base += 2 * (kSegments + 1);
    for (float y : {1.0f, -1.0f}) {  // the caps: fans
        const Ogre::Vector3 n(0, y, 0);
        mo.position(0, y, 0);
        mo.normal(n);
        mo.textureCoord(0.5f, 0.5f);
        for (int i = 0; i <= kSegments; ++i) {
            const float a = 2 * kPi * static_cast<float>(i) / kSegments;
            mo.position(std::cos(a), y, -std::sin(a));
            mo.normal(n);
            mo.textureCoord(0.5f + 0.5f * std::cos(a), 0.5f + 0.5f * std::sin(a));
        }
        for (int i = 0; i < kSegments; ++i)
            if (y > 0) mo.triangle(base, base + 1 + i, base + 2 + i);
            else mo.triangle(base, base + 2 + i, base + 1 + i);
        base += kSegments + 2;
    }
}

void buildSphere(Ogre::ManualObject& mo) {
    const int rings = kSegments / 2;
    for (int r = 0; r <= rings; ++r) {
        const float phi = kPi * static_cast<float>(r) / rings;
        for (int i = 0; i <= kSegments; ++i) {
            const float a = 2 * kPi * static_cast<float>(i) / kSegments;
            const Ogre::Vector3 n(std::sin(phi) * std::cos(a), std::cos(phi), -std::sin(phi) * std::sin(a));
            mo.position(n);
            mo.normal(n);
            mo.textureCoord(static_cast<float>(i) / kSegments, static_cast<float>(r) / rings);
        }
    }
    for (int r = 0; r < rings; ++r)
        for (int i = 0; i < kSegments; ++i) {
            const Ogre::uint32 a = r * (kSegments + 1) + i, b = a + kSegments + 1;
            mo.quad(a, b, b + 1, a + 1);
        }
}
}  // namespace

const std::string& unitMesh(PropPose::Shape shape) {
    static const std::string names[] = {"Obscura/UnitBox", "Obscura/UnitCylinder", "Obscura/UnitSphere"};
    const std::string& name = names[static_cast<int>(shape)];
    if (!Ogre::MeshManager::getSingleton().resourceExists(name, Ogre::RGN_DEFAULT)) {
        Ogre::ManualObject mo(name + "Builder");
        mo.begin(kBuildMaterial, Ogre::RenderOperation::OT_TRIANGLE_LIST);
        if (shape == PropPose::Shape::Box) buildBox(mo);
        else if (shape == PropPose::Shape::Cylinder) buildCylinder(mo);
        else buildSphere(mo);
        mo.end();
        mo.convertToMesh(name);
    }
    return name;
}

PropView::PropView(Ogre::SceneManager& scene, LevelMaterials& materials) : scene_(scene), materials_(materials) {}

PropView::~PropView() {
    for (auto& it : items_) {
        scene_.destroyEntity(it.entity);
        scene_.destroySceneNode(it.node);
    }
}

void PropView::update(const std::vector<PropPose>& poses) {
    for (size_t i = 0; i < poses.size(); ++i) {
        const auto& p = poses[i];
        const std::string material = p.material.empty() ? "crate" : p.material;
        if (i < items_.size() && (items_[i].shape != p.shape || items_[i].material != material)) {
            scene_.destroyEntity(items_[i].entity);
            items_[i].entity = nullptr;
        }
        if (i >= items_.size()) items_.push_back({scene_.getRootSceneNode()->createChildSceneNode(), nullptr, p.shape, material});
        auto& it = items_[i];
        if (!it.entity) {
            it.entity = scene_.createEntity(unitMesh(p.shape));
            it.entity->setMaterialName(materials_.resolve(material));
            it.node->attachObject(it.entity);
            it.shape = p.shape;
            it.material = material;
        }
        it.node->setVisible(true);
        it.node->setPosition(static_cast<float>(p.position.x), static_cast<float>(p.position.y), static_cast<float>(p.position.z));
        it.node->setOrientation(static_cast<float>(p.qw), static_cast<float>(p.qx), static_cast<float>(p.qy), static_cast<float>(p.qz));
        const auto& h = p.halfExtents;
        // Round shapes: x is the radius (and z); the sphere's y too.
        const double sy = p.shape == PropPose::Shape::Sphere ? h.x : h.y;
        const double sz = p.shape == PropPose::Shape::Box ? h.z : h.x;
        it.node->setScale(static_cast<float>(h.x), static_cast<float>(sy), static_cast<float>(sz));
    }
    for (size_t i = poses.size(); i < items_.size(); ++i) items_[i].node->setVisible(false);
}

}  // namespace obscura::render
