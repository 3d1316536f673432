// See model_loader.h.
#include "render/model_loader.h"

#include "map/asset_path.h"
#include "map/input_file.h"
#include "render/level_materials.h"

#include <Ogre.h>
#include <OgreMeshSerializer.h>

#include <filesystem>

namespace obscura::render {

namespace fs = std::filesystem;

namespace {
// Swaps a material name the mesh asks for but nobody defined for a generated fallback, while
// the mesh loads (before OGRE would drop the name and warn).
class FallbackMaterials : public Ogre::MeshSerializerListener {
public:
    FallbackMaterials(LevelMaterials& materials, const std::string& group) : materials_(materials), group_(group) {
        previous_ = Ogre::MeshManager::getSingleton().getListener();
        Ogre::MeshManager::getSingleton().setListener(this);
    }
    ~FallbackMaterials() override { Ogre::MeshManager::getSingleton().setListener(previous_); }
    void processMaterialName(Ogre::Mesh*, Ogre::String* name) override {
        if (!Ogre::MaterialManager::getSingleton().resourceExists(*name, group_)) *name = materials_.resolve(*name);
    }
    void processSkeletonName(Ogre::Mesh*, Ogre::String*) override {}
    void processMeshCompleted(Ogre::Mesh*) override {}

private:
    LevelMaterials& materials_;
    std::string group_;
    Ogre::MeshSerializerListener* previous_ = nullptr;
};

// Appends a submesh's triangles (transformed to world space) to `out`.
void appendTriangles(const Ogre::VertexData* vd, const Ogre::IndexData* id, const Ogre::Affine3& xf,
                     TriangleMesh& out) {
    const Ogre::VertexElement* pos = vd->vertexDeclaration->findElementBySemantic(Ogre::VES_POSITION);
    Ogre::HardwareVertexBufferSharedPtr vb = vd->vertexBufferBinding->getBuffer(pos->getSource());
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    {
        Ogre::HardwareBufferLockGuard lock(vb, Ogre::HardwareBuffer::HBL_READ_ONLY);
        const auto* data = static_cast<const unsigned char*>(lock.pData) + vd->vertexStart * vb->getVertexSize();
        for (size_t i = 0; i < vd->vertexCount; ++i, data += vb->getVertexSize()) {
            float* p;
            pos->baseVertexPointerToElement(const_cast<unsigned char*>(data), &p);
            const Ogre::Vector3 w = xf * Ogre::Vector3(p[0], p[1], p[2]);
            out.vertices.push_back({w.x, w.y, w.z});
        }
    }
    Ogre::HardwareIndexBufferSharedPtr ib = id->indexBuffer;
    Ogre::HardwareBufferLockGuard lock(ib, Ogre::HardwareBuffer::HBL_READ_ONLY);
    const bool is32 = ib->getType() == Ogre::HardwareIndexBuffer::IT_32BIT;
    for (size_t i = 0; i < id->indexCount; ++i) {
        const size_t k = id->indexStart + i;
        const std::uint32_t index = is32 ? static_cast<const std::uint32_t*>(lock.pData)[k]
                                         : static_cast<const std::uint16_t*>(lock.pData)[k];
        out.indices.push_back(base + index);
    }
}
}  // namespace

TriangleMesh placeModel(Ogre::SceneManager& scene, const map::LevelModel& model, const std::string& levelPath,
                        const std::vector<std::string>& searchDirs, const std::string& group, LevelMaterials& materials) {
    auto& rgm = Ogre::ResourceGroupManager::getSingleton();
    const std::string where = levelPath + ":" + std::to_string(model.pos.line) + ": misc_model";
    const std::string shown = "'" + errorText(model.mesh) + "'";
    // A path is resolved (symlinks, `..`) and must stay inside the level's folder or a media
    // folder before its folder becomes a resource location; a bare name may also come from the
    // resource group (our own media locations).
    const map::AssetPath found = map::LevelFiles(levelPath, searchDirs).find(model.mesh);
    if (!found.error.empty()) throw std::runtime_error(where + " 'model' " + shown + " " + found.error + "; a level's files must live there");
    std::string meshName;
    if (!found.file.empty()) {
        const std::string dir = fs::path(found.file).parent_path().string();
        if (!rgm.resourceLocationExists(dir, group)) rgm.addResourceLocation(dir, "FileSystem", group);
        meshName = fs::path(found.file).filename().string();
    } else if (map::isBareName(model.mesh) && rgm.resourceExists(group, model.mesh)) {
        meshName = model.mesh;
    }
    if (meshName.empty() || !rgm.resourceExists(group, meshName))
        throw std::runtime_error(where + " mesh " + shown + " not found (looked in the level's folder, the data folder and the media)");

    Ogre::MeshPtr mesh;
    try {
        FallbackMaterials fallbacks(materials, group);
        mesh = Ogre::MeshManager::getSingleton().load(meshName, group);
    } catch (const Ogre::Exception& e) {
        throw std::runtime_error(where + " mesh " + shown + " cannot be loaded: " + errorText(e.getDescription(), 300));
    }
    Ogre::Entity* entity = scene.createEntity(mesh);
    const Ogre::Affine3 xf = modelTransform(model);
    Ogre::Vector3 position, scale;
    Ogre::Quaternion orientation;
    xf.decomposition(position, scale, orientation);
    Ogre::SceneNode* node = scene.getRootSceneNode()->createChildSceneNode(position, orientation);
    node->setScale(scale);
    node->attachObject(entity);
    return meshTriangles(*mesh, modelTransform(model));
}

Ogre::Affine3 modelTransform(const map::LevelModel& model) {
    const Ogre::Vector3 origin(static_cast<float>(model.origin.x), static_cast<float>(model.origin.y),
                               static_cast<float>(model.origin.z));
    const Ogre::Quaternion yaw(Ogre::Radian(static_cast<float>(model.yaw)), Ogre::Vector3::UNIT_Y);
    return Ogre::Affine3(origin, yaw, Ogre::Vector3(static_cast<float>(model.scale)));
}

TriangleMesh meshTriangles(const Ogre::Mesh& mesh, const Ogre::Affine3& xf) {
    TriangleMesh tris;
    for (unsigned i = 0; i < mesh.getNumSubMeshes(); ++i) {
        const Ogre::SubMesh* sm = mesh.getSubMesh(i);
        appendTriangles(sm->useSharedVertices ? mesh.sharedVertexData : sm->vertexData, sm->indexData, xf, tris);
    }
    return tris;
}

}  // namespace obscura::render
