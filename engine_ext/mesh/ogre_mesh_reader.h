// A plain C++ reader for OGRE's binary .mesh files (MeshSerializer v1.10 .. v1.100), so the
// simulation can build colliders and smoke obstacles from model files without the renderer.
// No OGRE include, no OGRE link. What is read, what is skipped and the limits: README.md here.
//
// Every read is bounds-checked; a bad file throws std::runtime_error naming the file, the byte
// offset and the problem. Counts are capped (kMax* below) and checked against the bytes that are
// really there before anything is allocated, so a corrupt or hostile file cannot crash, hang or
// allocate more than a small multiple of its own size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/triangle_mesh.h"
#include "core/vec3.h"

namespace obscura::mesh {

constexpr std::size_t kMaxFileBytes = std::size_t{256} << 20;  // 256 MiB
constexpr std::uint32_t kMaxVertices = 1u << 24;                // per vertex data (shared or a submesh's)
constexpr std::uint32_t kMaxIndices = 1u << 26;                 // per submesh, and in all the triangle lists

// OGRE's RenderOperation::OperationType values, as stored in M_SUBMESH_OPERATION.
enum class Operation : std::uint16_t {
    PointList = 1,
    LineList = 2,
    LineStrip = 3,
    TriangleList = 4,
    TriangleStrip = 5,
    TriangleFan = 6,
};

struct MeshFile {
    struct SubMesh {
        std::string material;                         // as written in the file
        bool sharedVertices = false;                  // true: indices refer to MeshFile::sharedPositions
        Operation operation = Operation::TriangleList;  // as stored; `indices` is always a triangle list
        std::vector<Vec3> positions;                  // own vertices (empty when sharedVertices)
        std::vector<std::uint32_t> indices;           // triangle list, three per triangle; strips and fans
                                                      // converted, points and lines give none
    };
    struct Bounds {
        Vec3 min, max;
        double radius = 0;
    };

    std::string version;                // "[MeshSerializer_v1.100]", ...
    bool bigEndian = false;             // the file's byte order
    std::vector<Vec3> sharedPositions;  // the mesh's shared vertex data (may be empty)
    std::vector<SubMesh> submeshes;     // in file order
    std::optional<Bounds> bounds;       // M_MESH_BOUNDS, when present

    const std::vector<Vec3>& positionsOf(const SubMesh& s) const { return s.sharedVertices ? sharedPositions : s.positions; }
    std::size_t triangleCount() const;
};

// Diagnostics: one record per chunk the reader walked (for tests and dump tools).
struct ChunkRecord {
    std::uint16_t id = 0;
    int depth = 0;               // 0 = top level (M_MESH), 1 = its children, ...
    std::size_t offset = 0;      // of the chunk header
    std::uint32_t length = 0;    // as declared in the header (header included)
    std::size_t end = 0;         // where the reader finished the chunk (children included)
};

// Reads a .mesh file (regular files only; at most kMaxFileBytes).
MeshFile readOgreMesh(const std::string& path);
// Reads a .mesh image from memory; `name` names it in error messages. `chunks`, if given,
// receives the chunk records.
MeshFile readOgreMesh(const void* data, std::size_t size, const std::string& name,
                      std::vector<ChunkRecord>* chunks = nullptr);

// Where a model sits: translate(origin) * rotateY(yaw) * uniform scale, yaw in radians about +Y
// (right-handed, Y up: yaw = pi/2 turns +X into -Z), exactly as render::modelTransform builds
// its Ogre::Affine3 from a map::LevelModel.
struct Transform {
    Vec3 origin;
    double yaw = 0;
    double scale = 1;
};

// The transform is evaluated in single precision step by step as OGRE 1.12 does
// (Quaternion(Radian(yaw), UNIT_Y) -> rotation matrix -> Affine3(origin, q, scale) * point), so
// results are bit-identical to the renderer's path (see README.md for the one caveat).
Vec3 transformPoint(const Transform& transform, const Vec3& point);

// Every submesh's triangles in world space, in file order. Each submesh's own vertices are
// appended once; the shared vertices are appended once, for all the submeshes that use them.
// Submeshes without triangles (points, lines) contribute nothing.
TriangleMesh meshTriangles(const MeshFile& mesh, const Transform& transform = {});

}  // namespace obscura::mesh
