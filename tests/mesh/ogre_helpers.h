// OGRE itself, without a GPU (software buffers, as OgreXMLConverter runs it): the reference the
// .mesh reader is compared with. Only the tests link OgreMain; the reader does not.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Ogre.h>

namespace obscura::mesh::testing {

// Starts OGRE once for the whole test executable (log to memory only).
void ensureOgre();

// What OGRE's own loader made of a mesh, read back from its buffers.
struct OgreMeshView {
    struct Sub {
        std::string material;      // the name OGRE's serializer read (via its listener)
        bool shared = false;
        int operation = 4;
        std::vector<float> positions;  // xyz of the submesh's own vertex data (empty when shared)
        std::vector<std::uint32_t> indices;  // the index buffer as stored
        bool indices32 = false;
    };
    std::vector<float> sharedPositions;
    std::vector<Sub> subs;
    Ogre::AxisAlignedBox bounds;
    float radius = 0;
    const std::vector<float>& positionsOf(const Sub& s) const { return s.shared ? sharedPositions : s.positions; }
};

std::vector<std::uint8_t> readBytes(const std::string& path);
OgreMeshView viewOf(const Ogre::Mesh& mesh, const std::vector<std::string>& materials);
// Imports a .mesh image with Ogre::MeshSerializer (the code MeshManager::load runs); the
// caller removes the mesh from the MeshManager. `materials` gets the names the serializer read.
Ogre::MeshPtr importWithOgre(const std::vector<std::uint8_t>& bytes, std::vector<std::string>* materials = nullptr);
// The same, as a view (the mesh is removed again).
OgreMeshView loadWithOgre(const std::vector<std::uint8_t>& bytes);
// Writes a mesh with Ogre::MeshSerializer::exportMesh.
std::vector<std::uint8_t> writeWithOgre(const Ogre::Mesh& mesh, Ogre::MeshVersion version,
                                        Ogre::Serializer::Endian endian = Ogre::Serializer::ENDIAN_NATIVE);

// The triangle list a submesh's index buffer and operation type stand for (the test's own,
// independent spelling of what the reader does: strips flip every other triangle, degenerate
// triangles of strips and fans are dropped, no indices means the vertices in order).
std::vector<std::uint32_t> expectedTriangles(const OgreMeshView::Sub& s, std::size_t vertexCount);

// Meshes built with OGRE's API.
enum class Layout {
    PositionOnly,  // one buffer, float3 position
    Interleaved,   // one buffer: normal, position, uv (position at offset 12)
    SplitSources,  // source 0: normal + uv; source 1: position
};
struct MeshSpec {
    bool shared = false;  // all submeshes on shared vertex data
    bool mixed = false;   // submesh 0 shared, the others with their own vertex data
    bool indices32 = false;
    Layout layout = Layout::Interleaved;
    Ogre::RenderOperation::OperationType operation = Ogre::RenderOperation::OT_TRIANGLE_LIST;
    int submeshes = 2;
    int vertices = 40;  // per vertex data
    int indices = 60;   // per submesh (0: non-indexed)
    unsigned seed = 1;
};
Ogre::MeshPtr buildMesh(const MeshSpec& spec);

// Everything else a mesh may carry, so the reader has to step over it: generated or manual LOD
// levels, edge lists, poses (with normals), morph and pose animations, a submesh name table,
// extremes, bone assignments, texture aliases.
enum class Lod { None, Generated, Manual };
void addExtras(Ogre::Mesh& mesh, Lod lod, bool edgeLists);

const char* versionName(Ogre::MeshVersion v);

}  // namespace obscura::mesh::testing
