// See ogre_helpers.h.
#include "ogre_helpers.h"

#include <OgreDefaultHardwareBufferManager.h>
#include <OgreLodStrategy.h>
#include <OgreMeshSerializer.h>

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <numeric>
#include <stdexcept>

namespace obscura::mesh::testing {

namespace {

// OGRE for the whole process: started before the first test, torn down after the last.
class OgreEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        log_ = new Ogre::LogManager();
        log_->createLog("test_mesh-ogre.log", true, false, true);  // no stdout, no file
        root_ = new Ogre::Root("", "", "");
        buffers_ = new Ogre::DefaultHardwareBufferManager();
    }
    void TearDown() override {
        Ogre::MeshManager::getSingleton().removeAll();
        delete buffers_;
        delete root_;
        delete log_;
        root_ = nullptr;
    }
    bool started() const { return root_ != nullptr; }

private:
    Ogre::LogManager* log_ = nullptr;
    Ogre::Root* root_ = nullptr;
    Ogre::DefaultHardwareBufferManager* buffers_ = nullptr;
};

OgreEnvironment* const environment =
    static_cast<OgreEnvironment*>(::testing::AddGlobalTestEnvironment(new OgreEnvironment));

// Records every material name the serializer reads and makes sure the material exists, so
// SubMesh::getMaterialName() keeps it (OgreXMLConverter does the same).
class MaterialNames : public Ogre::MeshSerializerListener {
public:
    std::vector<std::string> names;
    void processMaterialName(Ogre::Mesh* mesh, Ogre::String* name) override {
        names.push_back(*name);
        if (!name->empty()) Ogre::MaterialManager::getSingleton().createOrRetrieve(*name, mesh->getGroup());
    }
    void processSkeletonName(Ogre::Mesh*, Ogre::String*) override {}
    void processMeshCompleted(Ogre::Mesh*) override {}
};

std::vector<float> positionsOf(const Ogre::VertexData* vd) {
    std::vector<float> out;
    if (!vd) return out;
    const Ogre::VertexElement* pos = vd->vertexDeclaration->findElementBySemantic(Ogre::VES_POSITION);
    if (!pos || vd->vertexCount == 0) return out;
    Ogre::HardwareVertexBufferSharedPtr vb = vd->vertexBufferBinding->getBuffer(pos->getSource());
    Ogre::HardwareBufferLockGuard lock(vb, Ogre::HardwareBuffer::HBL_READ_ONLY);
    const auto* data = static_cast<unsigned char*>(lock.pData) + vd->vertexStart * vb->getVertexSize();
    for (size_t i = 0; i < vd->vertexCount; ++i, data += vb->getVertexSize()) {
        float* p;
        pos->baseVertexPointerToElement(const_cast<unsigned char*>(data), &p);
        out.insert(out.end(), {p[0], p[1], p[2]});
    }
    return out;
}

float nextFloat(unsigned& state) {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(static_cast<int>((state >> 8) % 200001u) - 100000) / 7919.0f;
}

unsigned nextIndex(unsigned& state, unsigned n) {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) % n;
}

Ogre::MaterialPtr material(const std::string& name) {
    return Ogre::static_pointer_cast<Ogre::Material>(
        Ogre::MaterialManager::getSingleton().createOrRetrieve(name, "General").first);
}

// A vertex data block in the given layout; extends `box` by its positions.
Ogre::VertexData* makeVertexData(Layout layout, int count, unsigned& rng, Ogre::AxisAlignedBox& box) {
    auto* vd = new Ogre::VertexData();
    vd->vertexCount = count;
    Ogre::VertexDeclaration* decl = vd->vertexDeclaration;
    auto& hbm = Ogre::HardwareBufferManager::getSingleton();
    std::vector<float> positions;
    for (int i = 0; i < count; ++i) {
        const Ogre::Vector3 p(nextFloat(rng), nextFloat(rng), nextFloat(rng));
        positions.insert(positions.end(), {p.x, p.y, p.z});
        box.merge(p);
    }
    auto fill = [&](unsigned short source, size_t vertexSize, size_t posOffset, bool others) {
        std::vector<unsigned char> bytes(vertexSize * count);
        for (int i = 0; i < count; ++i) {
            unsigned char* v = bytes.data() + i * vertexSize;
            if (others) {
                // normal, colour and uv at their offsets: any recognisable values
                for (size_t k = 0; k < vertexSize / 4; ++k) {
                    const float f = 0.25f * static_cast<float>(k + i);
                    std::memcpy(v + 4 * k, &f, 4);
                }
            }
            if (posOffset != size_t(-1)) std::memcpy(v + posOffset, &positions[3 * i], 12);
        }
        Ogre::HardwareVertexBufferSharedPtr vb =
            hbm.createVertexBuffer(vertexSize, count, Ogre::HardwareBuffer::HBU_STATIC_WRITE_ONLY, true);
        vb->writeData(0, bytes.size(), bytes.data());
        vd->vertexBufferBinding->setBinding(source, vb);
    };
    switch (layout) {
    case Layout::PositionOnly:
        decl->addElement(0, 0, Ogre::VET_FLOAT3, Ogre::VES_POSITION);
        fill(0, 12, 0, false);
        break;
    case Layout::Interleaved:
        decl->addElement(0, 0, Ogre::VET_FLOAT3, Ogre::VES_NORMAL);
        decl->addElement(0, 12, Ogre::VET_FLOAT3, Ogre::VES_POSITION);
        decl->addElement(0, 24, Ogre::VET_COLOUR_ABGR, Ogre::VES_DIFFUSE);
        decl->addElement(0, 28, Ogre::VET_FLOAT2, Ogre::VES_TEXTURE_COORDINATES);
        fill(0, 36, 12, true);
        break;
    case Layout::SplitSources:
        decl->addElement(0, 0, Ogre::VET_FLOAT3, Ogre::VES_NORMAL);
        decl->addElement(0, 12, Ogre::VET_FLOAT2, Ogre::VES_TEXTURE_COORDINATES);
        decl->addElement(1, 0, Ogre::VET_FLOAT3, Ogre::VES_POSITION);
        fill(0, 20, size_t(-1), true);
        fill(1, 12, 0, false);
        break;
    }
    return vd;
}

Ogre::HardwareIndexBufferSharedPtr makeIndexBuffer(const std::vector<std::uint32_t>& indices, bool is32) {
    auto& hbm = Ogre::HardwareBufferManager::getSingleton();
    Ogre::HardwareIndexBufferSharedPtr ib = hbm.createIndexBuffer(
        is32 ? Ogre::HardwareIndexBuffer::IT_32BIT : Ogre::HardwareIndexBuffer::IT_16BIT, indices.size(),
        Ogre::HardwareBuffer::HBU_STATIC_WRITE_ONLY, true);
    if (is32) {
        ib->writeData(0, indices.size() * 4, indices.data());
    } else {
        std::vector<std::uint16_t> small(indices.begin(), indices.end());
        ib->writeData(0, small.size() * 2, small.data());
    }
    return ib;
}

int meshCounter = 0;

}  // namespace

void ensureOgre() {
    if (!environment->started()) throw std::logic_error("OGRE test environment not set up");
}

std::vector<std::uint8_t> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    return std::vector<std::uint8_t>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

OgreMeshView viewOf(const Ogre::Mesh& mesh, const std::vector<std::string>& materials) {
    OgreMeshView v;
    v.sharedPositions = positionsOf(mesh.sharedVertexData);
    for (unsigned i = 0; i < mesh.getNumSubMeshes(); ++i) {
        const Ogre::SubMesh* sm = mesh.getSubMesh(i);
        OgreMeshView::Sub s;
        s.material = i < materials.size() ? materials[i] : sm->getMaterialName();
        s.shared = sm->useSharedVertices;
        s.operation = sm->operationType;
        if (!s.shared) s.positions = positionsOf(sm->vertexData);
        const Ogre::IndexData* id = sm->indexData;
        if (id->indexCount > 0 && id->indexBuffer) {
            Ogre::HardwareBufferLockGuard lock(id->indexBuffer, Ogre::HardwareBuffer::HBL_READ_ONLY);
            s.indices32 = id->indexBuffer->getType() == Ogre::HardwareIndexBuffer::IT_32BIT;
            for (size_t k = id->indexStart; k < id->indexStart + id->indexCount; ++k)
                s.indices.push_back(s.indices32 ? static_cast<const std::uint32_t*>(lock.pData)[k]
                                                : static_cast<const std::uint16_t*>(lock.pData)[k]);
        }
        v.subs.push_back(std::move(s));
    }
    v.bounds = mesh.getBounds();
    v.radius = mesh.getBoundingSphereRadius();
    return v;
}

Ogre::MeshPtr importWithOgre(const std::vector<std::uint8_t>& bytes, std::vector<std::string>* materials) {
    ensureOgre();
    Ogre::MeshPtr mesh =
        Ogre::MeshManager::getSingleton().createManual("ogre-reference-" + std::to_string(meshCounter++), "General");
    Ogre::DataStreamPtr stream(
        new Ogre::MemoryDataStream(const_cast<std::uint8_t*>(bytes.data()), bytes.size(), false, true));
    MaterialNames names;
    Ogre::MeshSerializer serializer;
    serializer.setListener(&names);
    serializer.importMesh(stream, mesh.get());
    mesh->load();  // a manual resource: only marks it loaded, so that it frees its submeshes
    if (materials) *materials = names.names;
    return mesh;
}

OgreMeshView loadWithOgre(const std::vector<std::uint8_t>& bytes) {
    std::vector<std::string> materials;
    Ogre::MeshPtr mesh = importWithOgre(bytes, &materials);
    OgreMeshView v = viewOf(*mesh, materials);
    Ogre::MeshManager::getSingleton().remove(mesh);
    return v;
}

std::vector<std::uint8_t> writeWithOgre(const Ogre::Mesh& mesh, Ogre::MeshVersion version, Ogre::Serializer::Endian endian) {
    ensureOgre();
    const size_t capacity = size_t{32} << 20;
    auto stream = std::make_shared<Ogre::MemoryDataStream>(capacity, true, false);
    Ogre::MeshSerializer serializer;
    serializer.exportMesh(&mesh, Ogre::DataStreamPtr(stream), version, endian);
    const size_t size = stream->tell();
    if (size >= capacity) throw std::runtime_error("test mesh larger than the export buffer");
    return std::vector<std::uint8_t>(stream->getPtr(), stream->getPtr() + size);
}

std::vector<std::uint32_t> expectedTriangles(const OgreMeshView::Sub& s, std::size_t vertexCount) {
    std::vector<std::uint32_t> in = s.indices;
    if (in.empty()) {
        in.resize(vertexCount);
        std::iota(in.begin(), in.end(), 0u);
    }
    std::vector<std::uint32_t> out;
    auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (a != b && b != c && c != a) out.insert(out.end(), {a, b, c});
    };
    switch (s.operation) {
    case Ogre::RenderOperation::OT_TRIANGLE_LIST:
        out.assign(in.begin(), in.begin() + in.size() / 3 * 3);
        break;
    case Ogre::RenderOperation::OT_TRIANGLE_STRIP:
        for (size_t t = 0; t + 2 < in.size(); ++t) {
            if (t % 2 == 0)
                add(in[t], in[t + 1], in[t + 2]);
            else
                add(in[t + 1], in[t], in[t + 2]);
        }
        break;
    case Ogre::RenderOperation::OT_TRIANGLE_FAN:
        for (size_t t = 2; t < in.size(); ++t) add(in[0], in[t - 1], in[t]);
        break;
    default:  // points, lines
        break;
    }
    return out;
}

Ogre::MeshPtr buildMesh(const MeshSpec& spec) {
    ensureOgre();
    Ogre::MeshPtr mesh =
        Ogre::MeshManager::getSingleton().createManual("built-" + std::to_string(meshCounter++), "General");
    unsigned rng = spec.seed * 7919u + 17u;
    Ogre::AxisAlignedBox box;
    if (spec.shared || spec.mixed) mesh->sharedVertexData = makeVertexData(spec.layout, spec.vertices, rng, box);
    for (int i = 0; i < spec.submeshes; ++i) {
        Ogre::SubMesh* sm = mesh->createSubMesh();
        sm->setMaterial(material("MeshTest/Material" + std::to_string(i)));
        sm->useSharedVertices = spec.shared || (spec.mixed && i == 0);
        if (!sm->useSharedVertices) sm->vertexData = makeVertexData(spec.layout, spec.vertices + 3 * i, rng, box);
        const unsigned n = static_cast<unsigned>(sm->useSharedVertices ? spec.vertices : spec.vertices + 3 * i);
        sm->operationType = spec.operation;
        if (spec.indices > 0) {
            std::vector<std::uint32_t> idx;
            // lists: whole triangles (an incomplete one is tested on its own); strips, fans, points
            // and lines: any count
            const int count = spec.indices + (spec.operation == Ogre::RenderOperation::OT_TRIANGLE_LIST ? 3 * i : i);
            for (int k = 0; k < count; ++k) {
                idx.push_back(nextIndex(rng, n));
                // strips and fans: now and then a repeated index (a degenerate join)
                if (spec.operation != Ogre::RenderOperation::OT_TRIANGLE_LIST && k % 7 == 3) idx.push_back(idx.back());
            }
            sm->indexData->indexBuffer = makeIndexBuffer(idx, spec.indices32);
            sm->indexData->indexStart = 0;
            sm->indexData->indexCount = idx.size();
        } else {
            sm->indexData->indexCount = 0;
        }
    }
    mesh->_setBounds(box, false);
    mesh->_setBoundingSphereRadius(std::max(box.getMinimum().length(), box.getMaximum().length()));
    mesh->load();  // see importWithOgre
    return mesh;
}

void addExtras(Ogre::Mesh& mesh, Lod lod, bool edgeLists) {
    const unsigned subs = mesh.getNumSubMeshes();
    for (unsigned i = 0; i < subs; ++i) {
        Ogre::SubMesh* sm = mesh.getSubMesh(i);
        mesh.nameSubMesh("part" + std::to_string(i), static_cast<Ogre::ushort>(i));
        sm->generateExtremes(4);
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
        sm->addTextureAlias("diffuse", "stone" + std::to_string(i) + ".png");  // deprecated, still written
#pragma GCC diagnostic pop
        if (!sm->useSharedVertices) {
            Ogre::VertexBoneAssignment a;
            a.vertexIndex = 1;
            a.boneIndex = 0;
            a.weight = 1.0f;
            sm->addBoneAssignment(a);
        }
    }
    if (lod == Lod::Generated) {
        mesh._setLodInfo(3);
        for (unsigned short level = 1; level < 3; ++level) {
            Ogre::MeshLodUsage u;
            u.userValue = 10.0f * level;
            u.value = mesh.getLodStrategy()->transformUserValue(u.userValue);
            mesh._setLodUsage(level, u);
        }
        for (unsigned i = 0; i < subs; ++i) {
            const Ogre::IndexData* full = mesh.getSubMesh(i)->indexData;
            // level 1 has a buffer of its own; level 2 reuses it with fewer indices (the
            // writer's "buffer index" path)
            auto* l1 = full->clone(true);
            l1->indexCount = full->indexCount / 3 / 2 * 3;
            auto* l2 = new Ogre::IndexData();
            l2->indexBuffer = l1->indexBuffer;
            l2->indexStart = 0;
            l2->indexCount = l1->indexCount / 3 / 2 * 3;
            mesh._setSubMeshLodFaceList(static_cast<unsigned short>(i), 1, l1);
            mesh._setSubMeshLodFaceList(static_cast<unsigned short>(i), 2, l2);
        }
    } else if (lod == Lod::Manual) {
        mesh._setLodInfo(2);
        Ogre::MeshLodUsage u;
        u.userValue = 25.0f;
        u.value = mesh.getLodStrategy()->transformUserValue(u.userValue);
        u.manualName = "far_away.mesh";
        mesh._setLodUsage(1, u);
    }
    if (edgeLists) mesh.buildEdgeList();

    // Poses: one with normals, one without; on the shared vertices when there are any.
    const Ogre::ushort target = mesh.sharedVertexData ? 0 : 1;
    Ogre::Pose* p0 = mesh.createPose(target, "smile");
    p0->addVertex(0, Ogre::Vector3(0.1f, 0.2f, 0.3f), Ogre::Vector3(0, 1, 0));
    p0->addVertex(2, Ogre::Vector3(-0.1f, 0.0f, 0.5f), Ogre::Vector3(1, 0, 0));
    Ogre::Pose* p1 = mesh.createPose(target, "");
    p1->addVertex(1, Ogre::Vector3(0.0f, -0.25f, 0.0f));

    // A pose animation with a base keyframe, and a morph animation on a submesh's own vertices.
    Ogre::Animation* poses = mesh.createAnimation("blink", 2.0f);
    poses->setUseBaseKeyFrame(true, 0.0f, "");
    Ogre::VertexAnimationTrack* pt = poses->createVertexTrack(target, mesh.getVertexDataByTrackHandle(target), Ogre::VAT_POSE);
    pt->createVertexPoseKeyFrame(0.0f)->addPoseReference(0, 1.0f);
    Ogre::VertexPoseKeyFrame* k1 = pt->createVertexPoseKeyFrame(1.0f);
    k1->addPoseReference(0, 0.5f);
    k1->addPoseReference(1, 0.25f);
    for (unsigned i = 0; i < subs; ++i) {
        Ogre::SubMesh* sm = mesh.getSubMesh(i);
        if (sm->useSharedVertices) continue;
        const auto handle = static_cast<unsigned short>(i + 1);
        Ogre::Animation* morph = mesh.createAnimation("wobble" + std::to_string(i), 1.0f);
        Ogre::VertexAnimationTrack* mt = morph->createVertexTrack(handle, sm->vertexData, Ogre::VAT_MORPH);
        for (int key = 0; key < 2; ++key) {
            const size_t n = sm->vertexData->vertexCount;
            const size_t floats = key == 0 ? 3 : 6;  // the second keyframe carries normals
            std::vector<float> data(n * floats, 0.5f * static_cast<float>(key + 1));
            Ogre::HardwareVertexBufferSharedPtr vb = Ogre::HardwareBufferManager::getSingleton().createVertexBuffer(
                floats * 4, n, Ogre::HardwareBuffer::HBU_STATIC, true);
            vb->writeData(0, data.size() * 4, data.data());
            mt->createVertexMorphKeyFrame(static_cast<float>(key))->setVertexBuffer(vb);
        }
        break;
    }
}

const char* versionName(Ogre::MeshVersion v) {
    switch (v) {
    case Ogre::MESH_VERSION_LATEST: return "latest (v1.100)";
    case Ogre::MESH_VERSION_1_10: return "v1.100";
    case Ogre::MESH_VERSION_1_8: return "v1.8";
    case Ogre::MESH_VERSION_1_7: return "v1.41";
    case Ogre::MESH_VERSION_1_4: return "v1.40";
    case Ogre::MESH_VERSION_1_0: return "v1.30";
    default: return "legacy";
    }
}

}  // namespace obscura::mesh::testing
