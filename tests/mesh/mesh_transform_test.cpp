// meshTriangles and transformPoint against OGRE's own transform: the single-precision result of
// Affine3(origin, Quaternion(Radian(yaw), UNIT_Y), Vector3(scale)) * point, bit for bit, the
// way render::modelTransform and render::meshTriangles use it.
#include "mesh_compare.h"

#include <cmath>
#include <cstring>
#include <filesystem>

using namespace obscura;
using namespace obscura::mesh;
using namespace obscura::mesh::testing;

namespace {

// render::modelTransform, spelled out with OGRE's types.
Ogre::Affine3 ogreTransform(const Transform& t) {
    const Ogre::Vector3 origin(static_cast<float>(t.origin.x), static_cast<float>(t.origin.y), static_cast<float>(t.origin.z));
    const Ogre::Quaternion yaw(Ogre::Radian(static_cast<float>(t.yaw)), Ogre::Vector3::UNIT_Y);
    return Ogre::Affine3(origin, yaw, Ogre::Vector3(static_cast<float>(t.scale)));
}

bool sameBits(double mine, float ogre) {
    const float f = static_cast<float>(mine);
    if (static_cast<double>(f) != mine) return false;  // the reader's results are floats
    return std::memcmp(&f, &ogre, sizeof f) == 0;
}

// render::meshTriangles: every submesh's vertex data transformed and appended, then its indices.
TriangleMesh rendererTriangles(const Ogre::Mesh& mesh, const Ogre::Affine3& xf) {
    TriangleMesh out;
    for (unsigned i = 0; i < mesh.getNumSubMeshes(); ++i) {
        const Ogre::SubMesh* sm = mesh.getSubMesh(i);
        const Ogre::VertexData* vd = sm->useSharedVertices ? mesh.sharedVertexData : sm->vertexData;
        const Ogre::VertexElement* pos = vd->vertexDeclaration->findElementBySemantic(Ogre::VES_POSITION);
        Ogre::HardwareVertexBufferSharedPtr vb = vd->vertexBufferBinding->getBuffer(pos->getSource());
        const auto base = static_cast<std::uint32_t>(out.vertices.size());
        {
            Ogre::HardwareBufferLockGuard lock(vb, Ogre::HardwareBuffer::HBL_READ_ONLY);
            const auto* data = static_cast<const unsigned char*>(lock.pData) + vd->vertexStart * vb->getVertexSize();
            for (size_t k = 0; k < vd->vertexCount; ++k, data += vb->getVertexSize()) {
                float* p;
                pos->baseVertexPointerToElement(const_cast<unsigned char*>(data), &p);
                const Ogre::Vector3 w = xf * Ogre::Vector3(p[0], p[1], p[2]);
                out.vertices.push_back({w.x, w.y, w.z});
            }
        }
        Ogre::HardwareBufferLockGuard lock(sm->indexData->indexBuffer, Ogre::HardwareBuffer::HBL_READ_ONLY);
        const bool is32 = sm->indexData->indexBuffer->getType() == Ogre::HardwareIndexBuffer::IT_32BIT;
        for (size_t k = 0; k < sm->indexData->indexCount; ++k) {
            const size_t at = sm->indexData->indexStart + k;
            out.indices.push_back(base + (is32 ? static_cast<const std::uint32_t*>(lock.pData)[at]
                                               : static_cast<const std::uint16_t*>(lock.pData)[at]));
        }
    }
    return out;
}

// The same triangles with the same corners, in the same order (the vertex arrays may differ:
// the reader appends shared vertices once).
::testing::AssertionResult sameTriangles(const TriangleMesh& mine, const TriangleMesh& ref) {
    if (mine.indices.size() != ref.indices.size())
        return ::testing::AssertionFailure() << mine.indices.size() << " indices vs " << ref.indices.size();
    for (size_t k = 0; k < mine.indices.size(); ++k) {
        const Vec3& a = mine.vertices.at(mine.indices[k]);
        const Vec3& b = ref.vertices.at(ref.indices[k]);
        if (a != b)
            return ::testing::AssertionFailure() << "corner " << k << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs ("
                                                 << b.x << ", " << b.y << ", " << b.z << ")";
    }
    return ::testing::AssertionSuccess();
}

}  // namespace

TEST(MeshTransform, MatchesOgreAffine3BitForBit) {
    const double pi = 3.14159265358979323846;
    std::vector<double> yaws = {0, 1e-7, -1e-7, 0.1, pi / 2, -pi / 2, pi, 1.5 * pi, 2 * pi, 10, -123.456, 1e4};
    for (int i = -400; i <= 400; ++i) yaws.push_back(i * 0.0173);
    const double scales[] = {1, 0.3, 2.54, 1.0 / 3, 1000, 0.001};
    const Vec3 origins[] = {{0, 0, 0}, {1.5, -2, 3.25}, {1e4, -3e3, 0.001}, {-0.1, 0.2, -0.3}};
    const Vec3 points[] = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {-0.0, 0.0, -0.0}, {3.1, -4.7, 12.9}, {-1e3, 7.5e2, 1e-3},
                           {0.333333, 0.5, -0.25}};
    int checked = 0;
    for (double yaw : yaws)
        for (double scale : scales)
            for (const Vec3& origin : origins) {
                const Transform t{origin, yaw, scale};
                const Ogre::Affine3 xf = ogreTransform(t);
                for (const Vec3& p : points) {
                    const Ogre::Vector3 w =
                        xf * Ogre::Vector3(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
                    const Vec3 m = transformPoint(t, p);
                    ASSERT_TRUE(sameBits(m.x, w.x) && sameBits(m.y, w.y) && sameBits(m.z, w.z))
                        << "yaw " << yaw << " scale " << scale << " origin (" << origin.x << ", " << origin.y << ", "
                        << origin.z << ") point (" << p.x << ", " << p.y << ", " << p.z << "): (" << m.x << ", " << m.y
                        << ", " << m.z << ") vs OGRE (" << w.x << ", " << w.y << ", " << w.z << ")";
                    ++checked;
                }
            }
    EXPECT_GT(checked, 50000);
}

TEST(MeshTransform, YawTurnsLikeOgre) {
    const double pi = 3.14159265358979323846;
    // Right-handed, Y up: a quarter turn of yaw takes +X to -Z and +Z to +X.
    const Vec3 x = transformPoint({{0, 0, 0}, pi / 2, 1}, {1, 0, 0});
    EXPECT_NEAR(x.x, 0, 1e-6);
    EXPECT_NEAR(x.y, 0, 1e-6);
    EXPECT_NEAR(x.z, -1, 1e-6);
    const Vec3 z = transformPoint({{0, 0, 0}, pi / 2, 1}, {0, 0, 1});
    EXPECT_NEAR(z.x, 1, 1e-6);
    EXPECT_NEAR(z.z, 0, 1e-6);
    const Ogre::Vector3 o = Ogre::Quaternion(Ogre::Radian(static_cast<float>(pi / 2)), Ogre::Vector3::UNIT_Y) * Ogre::Vector3::UNIT_X;
    EXPECT_NEAR(o.z, -1, 1e-6);
    // Scale, then rotate, then translate.
    const Vec3 p = transformPoint({{10, 20, 30}, pi, 2}, {1, 2, 3});
    EXPECT_NEAR(p.x, 8, 1e-5);
    EXPECT_NEAR(p.y, 24, 1e-5);
    EXPECT_NEAR(p.z, 24, 1e-5);
}

TEST(MeshTransform, SibenikTrianglesMatchTheRendererPath) {
    const std::string path = std::string(OBSCURA_THIRD_PARTY_DIR) + "/scenes/sibenik.mesh";
    const std::vector<std::uint8_t> bytes = readBytes(path);
    const MeshFile mine = readOgreMesh(path);
    Ogre::MeshPtr ogre = importWithOgre(bytes);
    for (const Transform& t : {Transform{{0, 0, 0}, 0, 0.3}, Transform{{1.25, -0.5, 3}, 0.7, 0.3},
                               Transform{{-40, 2, 17.5}, -2.9, 1.7}}) {
        const TriangleMesh a = meshTriangles(mine, t);
        const TriangleMesh b = rendererTriangles(*ogre, ogreTransform(t));
        EXPECT_TRUE(sameTriangles(a, b));
        EXPECT_EQ(a.indices.size(), 3 * mine.triangleCount());
        // No submesh of Sibenik uses shared vertices: then the whole TriangleMesh is the
        // renderer's, vertex array and all (so tools/aoref's output does not change).
        EXPECT_TRUE(mine.sharedPositions.empty());
        EXPECT_TRUE(a.vertices == b.vertices);
        EXPECT_TRUE(a.indices == b.indices);
    }
    Ogre::MeshManager::getSingleton().remove(ogre);
}

TEST(MeshTransform, SharedVerticesAppendedOnce) {
    MeshSpec spec;
    spec.mixed = true;  // submesh 0 on the shared vertices
    spec.submeshes = 3;
    Ogre::MeshPtr built = buildMesh(spec);
    // and submesh 2 on the shared vertices as well
    Ogre::SubMesh* sm = built->getSubMesh(2);
    delete sm->vertexData;
    sm->vertexData = nullptr;
    sm->useSharedVertices = true;
    std::vector<std::uint16_t> idx = {0, 1, 2, 3, 4, 5};
    sm->indexData->indexBuffer = Ogre::HardwareBufferManager::getSingleton().createIndexBuffer(
        Ogre::HardwareIndexBuffer::IT_16BIT, idx.size(), Ogre::HardwareBuffer::HBU_STATIC, true);
    sm->indexData->indexBuffer->writeData(0, idx.size() * 2, idx.data());
    sm->indexData->indexCount = idx.size();
    const std::vector<std::uint8_t> bytes = writeWithOgre(*built, Ogre::MESH_VERSION_LATEST);
    Ogre::MeshManager::getSingleton().remove(built);

    const MeshFile mine = readOgreMesh(bytes.data(), bytes.size(), "shared.mesh");
    Ogre::MeshPtr ogre = importWithOgre(bytes);
    const Transform t{{3, 2, 1}, 1.1, 0.5};
    const TriangleMesh a = meshTriangles(mine, t);
    const TriangleMesh b = rendererTriangles(*ogre, ogreTransform(t));
    EXPECT_TRUE(sameTriangles(a, b));
    EXPECT_EQ(a.vertices.size(), mine.sharedPositions.size() + mine.submeshes[1].positions.size());
    EXPECT_EQ(b.vertices.size(), 2 * mine.sharedPositions.size() + mine.submeshes[1].positions.size());
    Ogre::MeshManager::getSingleton().remove(ogre);
}
