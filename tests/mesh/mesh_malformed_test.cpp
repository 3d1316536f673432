// Broken input: every failure is a std::runtime_error naming the file, the offset and the
// problem; nothing crashes, hangs or allocates without bound.
#include "chunk_writer.h"
#include "mesh_compare.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include <unistd.h>

using namespace obscura;
using namespace obscura::mesh;
using namespace obscura::mesh::testing;

namespace {

// The error message of reading `bytes`, or "" when it reads.
std::string errorOf(const std::vector<std::uint8_t>& bytes, const std::string& name = "broken.mesh") {
    try {
        readOgreMesh(bytes.data(), bytes.size(), name);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

::testing::AssertionResult failsWith(const std::vector<std::uint8_t>& bytes, const std::string& fragment) {
    const std::string e = errorOf(bytes);
    if (e.empty()) return ::testing::AssertionFailure() << "read without error";
    if (e.find("broken.mesh: offset ") != 0) return ::testing::AssertionFailure() << "no name/offset: " << e;
    if (e.find(fragment) == std::string::npos) return ::testing::AssertionFailure() << "'" << fragment << "' not in: " << e;
    return ::testing::AssertionSuccess() << e;
}

// A small mesh with a bit of everything, written by OGRE.
std::vector<std::uint8_t> smallMesh(Ogre::MeshVersion version, Ogre::Serializer::Endian endian = Ogre::Serializer::ENDIAN_LITTLE,
                                    bool extras = true) {
    MeshSpec spec;
    spec.mixed = true;
    spec.vertices = 6;
    spec.indices = 9;
    Ogre::MeshPtr mesh = buildMesh(spec);
    if (extras) addExtras(*mesh, Lod::Generated, true);
    std::vector<std::uint8_t> bytes = writeWithOgre(*mesh, version, endian);
    Ogre::MeshManager::getSingleton().remove(mesh);
    return bytes;
}

// The first chunk record with `id`.
ChunkRecord chunkOf(const std::vector<std::uint8_t>& bytes, std::uint16_t id, int nth = 0) {
    std::vector<ChunkRecord> chunks;
    readOgreMesh(bytes.data(), bytes.size(), "x", &chunks);
    for (const ChunkRecord& c : chunks)
        if (c.id == id && nth-- == 0) return c;
    throw std::logic_error("no such chunk in the test mesh");
}

void put32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) { std::memcpy(b.data() + at, &v, 4); }
void put16(std::vector<std::uint8_t>& b, std::size_t at, std::uint16_t v) { std::memcpy(b.data() + at, &v, 2); }

// The offset of the first submesh's fields after its material name.
std::size_t afterMaterial(const std::vector<std::uint8_t>& b, const ChunkRecord& submesh) {
    std::size_t at = submesh.offset + 6;
    while (b[at] != '\n') ++at;
    return at + 1;
}

}  // namespace

TEST(MeshMalformed, TruncatedAtEveryByte) {
    struct Case {
        const char* what;
        std::vector<std::uint8_t> bytes;
    };
    std::vector<Case> cases;
    cases.push_back({"v1.100", smallMesh(Ogre::MESH_VERSION_LATEST)});
    cases.push_back({"v1.100 big-endian", smallMesh(Ogre::MESH_VERSION_LATEST, Ogre::Serializer::ENDIAN_BIG)});
    cases.push_back({"v1.8", smallMesh(Ogre::MESH_VERSION_1_8)});
    cases.push_back({"v1.30 big-endian", smallMesh(Ogre::MESH_VERSION_1_0, Ogre::Serializer::ENDIAN_BIG)});
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        ASSERT_EQ(errorOf(c.bytes), "");
        std::vector<ChunkRecord> chunks;
        const MeshFile whole = readOgreMesh(c.bytes.data(), c.bytes.size(), "x", &chunks);
        const bool lengthsTrusted = whole.version == "[MeshSerializer_v1.100]";
        std::set<std::size_t> boundaries;
        for (const ChunkRecord& r : chunks) boundaries.insert({r.offset, r.end});
        int shorter = 0;
        for (std::size_t n = 0; n < c.bytes.size(); ++n) {
            const std::vector<std::uint8_t> cut(c.bytes.begin(), c.bytes.begin() + static_cast<std::ptrdiff_t>(n));
            const std::string e = errorOf(cut);
            if (e.empty()) {
                // Before v1.100 a file cut exactly between two chunks looks like a file with fewer
                // optional chunks (OGRE's older writers left no length to tell); a cut anywhere
                // else is always caught. In v1.100 every cut is caught (M_MESH's length).
                ASSERT_FALSE(lengthsTrusted) << "a file cut to " << n << " of " << c.bytes.size() << " bytes read without error";
                ASSERT_TRUE(boundaries.count(n)) << "a cut inside a chunk, at " << n << ", read without error";
                ++shorter;
            } else {
                ASSERT_EQ(e.find("broken.mesh: offset "), 0u) << e;
            }
        }
        std::cout << c.what << ": " << c.bytes.size() << " cuts, " << shorter << " at chunk boundaries read as shorter meshes\n";
    }
    // The messages say what ran short.
    const std::vector<std::uint8_t> v18 = smallMesh(Ogre::MESH_VERSION_1_8);
    const ChunkRecord sub = chunkOf(v18, 0x4000);
    std::vector<std::uint8_t> cut(v18.begin(), v18.begin() + static_cast<std::ptrdiff_t>(afterMaterial(v18, sub) + 8));
    EXPECT_TRUE(failsWith(cut, "truncated: submesh index data"));
    const std::vector<std::uint8_t> v1100 = smallMesh(Ogre::MESH_VERSION_LATEST, Ogre::Serializer::ENDIAN_LITTLE, false);
    cut.assign(v1100.begin(), v1100.end() - 1);
    EXPECT_TRUE(failsWith(cut, "M_MESH (0x3000) declares length"));
    EXPECT_TRUE(failsWith(cut, "runs past the end of the file"));
}

TEST(MeshMalformed, ChunkLengthPastTheEnd) {
    std::vector<std::uint8_t> b = smallMesh(Ogre::MESH_VERSION_LATEST);
    const ChunkRecord bounds = chunkOf(b, 0x9000);
    put32(b, bounds.offset + 2, 0x7FFFFFF0u);
    EXPECT_TRUE(failsWith(b, "M_MESH_BOUNDS (0x9000) declares length 2147483632, which runs past the end"));
    // Lengths shorter than the header.
    b = smallMesh(Ogre::MESH_VERSION_LATEST);
    put32(b, bounds.offset + 2, 5);
    EXPECT_TRUE(failsWith(b, "less than its 6-byte header"));
    // A top-level chunk the reader does not know is stepped over by its length, in any version.
    for (const auto version : {Ogre::MESH_VERSION_LATEST, Ogre::MESH_VERSION_1_8}) {
        b = smallMesh(version, Ogre::Serializer::ENDIAN_LITTLE, false);
        ChunkWriter extra;
        const auto at = extra.begin(0x2000);
        extra.u32(42);
        extra.end(at);
        b.insert(b.end(), extra.data.begin(), extra.data.end());
        EXPECT_EQ(errorOf(b), "");
        put32(b, b.size() - 10 + 2, 1000);
        EXPECT_TRUE(failsWith(b, "chunk 0x2000 declares length 1000, which runs past the end"));
    }
}

TEST(MeshMalformed, AbsurdCounts) {
    const std::vector<std::uint8_t> good = smallMesh(Ogre::MESH_VERSION_1_8);
    const ChunkRecord geometry = chunkOf(good, 0x5000);  // the shared vertex data
    std::vector<std::uint8_t> b = good;
    put32(b, geometry.offset + 6, 0xFFFFFFFFu);
    EXPECT_TRUE(failsWith(b, "vertex count 4294967295 exceeds the reader's limit of 16777216"));
    b = good;
    put32(b, geometry.offset + 6, kMaxVertices);  // under the cap, but the bytes are not there
    EXPECT_TRUE(failsWith(b, "truncated: vertex buffer data (16777216 vertices of 36 bytes)"));

    const ChunkRecord sub = chunkOf(good, 0x4000);
    const std::size_t count = afterMaterial(good, sub) + 1;  // after useSharedVertices
    b = good;
    put32(b, count, 0xFFFFFFF0u);
    EXPECT_TRUE(failsWith(b, "submesh index count 4294967280 exceeds the reader's limit"));
    b = good;
    put32(b, count, kMaxIndices);
    EXPECT_TRUE(failsWith(b, "truncated: submesh index data (67108864 indices)"));

    // Counts inside the parts that are stepped over are checked against the bytes too.
    const ChunkRecord edges = chunkOf(good, 0xB100);
    b = good;
    put32(b, edges.offset + 6 + 2 + 1 + 1, 0x40000000u);  // numTriangles (48 bytes each)
    EXPECT_TRUE(failsWith(b, "truncated: edge list triangles needs 51539607552 bytes"));
}

// Non-indexed submeshes on shared vertices cost nothing in the file but a triangle list each in
// memory: the lists of a mesh are capped together (this one allocates up to the cap, 256 MB).
TEST(MeshMalformed, TriangleListsCappedPerMesh) {
    const std::uint32_t vertices = 1u << 20;
    ChunkWriter w;
    w.header("[MeshSerializer_v1.8]");
    const auto m = w.begin(0x3000);
    w.boolean(false);
    const auto g = w.begin(0x5000);
    w.u32(vertices);
    const auto decl = w.begin(0x5100);
    const auto el = w.begin(0x5110);
    w.u16(0), w.u16(2), w.u16(1), w.u16(0), w.u16(0);  // source 0, float3, position, offset 0
    w.end(el);
    w.end(decl);
    const auto buf = w.begin(0x5200);
    w.u16(0), w.u16(12);
    const auto data = w.begin(0x5210);
    w.data.resize(w.data.size() + std::size_t{12} * vertices);
    w.end(data);
    w.end(buf);
    w.end(g);
    const int submeshes = static_cast<int>(kMaxIndices / vertices) + 1;
    for (int i = 0; i < submeshes; ++i) {
        const auto sub = w.begin(0x4000);
        w.str("S");
        w.boolean(true);  // shared vertices
        w.u32(0);         // no indices: the vertices in order, a list of a million indices
        w.boolean(false);
        w.end(sub);
    }
    w.end(m);
    EXPECT_TRUE(failsWith(w.data, "submesh " + std::to_string(submeshes - 1) +
                                      " ('S') would bring the mesh's triangle list past the reader's limit of 67108864 indices"));
    // one fewer submesh is exactly at the limit, and reads
    w.data.resize(w.data.size() - (6 + 2 + 1 + 4 + 1));
    const MeshFile ok = readOgreMesh(w.data.data(), w.data.size(), "at-the-limit.mesh");
    EXPECT_EQ(ok.triangleCount(), static_cast<std::size_t>(submeshes - 1) * (vertices / 3));
}

TEST(MeshMalformed, IndexOutOfRange) {
    std::vector<std::uint8_t> b = smallMesh(Ogre::MESH_VERSION_LATEST);
    const ChunkRecord sub = chunkOf(b, 0x4000);
    const std::size_t first = afterMaterial(b, sub) + 1 + 4 + 1;  // shared, count, 32-bit flag
    put16(b, first + 2, 6);                                       // the shared vertex data has 6 vertices
    EXPECT_TRUE(failsWith(b, "offset " + std::to_string(first + 2) + ": submesh 0 ('MeshTest/Material0'): index 6 out of range (6 vertices)"));
}

TEST(MeshMalformed, PositionsMustBeFloat3) {
    Ogre::MeshPtr mesh = buildMesh(MeshSpec{});
    Ogre::VertexData* vd = mesh->getSubMesh(0)->vertexData;
    // Position as four floats.
    vd->vertexDeclaration->removeAllElements();
    vd->vertexBufferBinding->unsetAllBindings();
    vd->vertexDeclaration->addElement(0, 0, Ogre::VET_FLOAT4, Ogre::VES_POSITION);
    Ogre::HardwareVertexBufferSharedPtr vb = Ogre::HardwareBufferManager::getSingleton().createVertexBuffer(
        16, vd->vertexCount, Ogre::HardwareBuffer::HBU_STATIC, true);
    const std::vector<float> ones(4 * vd->vertexCount, 1.0f);
    vb->writeData(0, ones.size() * 4, ones.data());
    vd->vertexBufferBinding->setBinding(0, vb);
    const std::vector<std::uint8_t> b = writeWithOgre(*mesh, Ogre::MESH_VERSION_LATEST);
    Ogre::MeshManager::getSingleton().remove(mesh);
    EXPECT_TRUE(failsWith(b, "position element has vertex type 3; only float3 positions (VET_FLOAT3 = 2) are supported"));
}

TEST(MeshMalformed, VertexSizeMustAgreeWithDeclaration) {
    std::vector<std::uint8_t> b = smallMesh(Ogre::MESH_VERSION_LATEST);
    const ChunkRecord buffer = chunkOf(b, 0x5200);
    put16(b, buffer.offset + 6 + 2, 40);
    EXPECT_TRUE(failsWith(b, "vertex buffer for source 0 has vertex size 40 but its declared elements add up to 36"));
}

TEST(MeshMalformed, HeaderAndVersion) {
    EXPECT_TRUE(failsWith({}, "too short"));
    EXPECT_TRUE(failsWith({0x89, 'P', 'N', 'G', '\r', '\n'}, "not an OGRE .mesh file: header id 0x5089"));
    ChunkWriter w;
    w.header("[MeshSerializer_v2.1 R2]");
    EXPECT_TRUE(failsWith(w.data, "unsupported mesh version '[MeshSerializer_v2.1 R2]'"));
    std::vector<std::uint8_t> noNewline = {0x00, 0x10};
    noNewline.insert(noNewline.end(), 200, 'x');
    EXPECT_TRUE(failsWith(noNewline, "unterminated version string"));
    ChunkWriter empty;
    empty.header("[MeshSerializer_v1.100]");
    EXPECT_TRUE(failsWith(empty.data, "no M_MESH chunk"));
}

TEST(MeshMalformed, StructuralErrors) {
    // A submesh with its own vertices and no geometry after it.
    ChunkWriter w;
    w.header("[MeshSerializer_v1.8]");
    const auto m = w.begin(0x3000);
    w.boolean(false);
    const auto s = w.begin(0x4000);
    w.str("M");
    w.boolean(false);
    w.u32(3);
    w.boolean(false);
    w.u16(0), w.u16(1), w.u16(2);
    w.end(s);
    const auto b = w.begin(0x9000);
    for (int i = 0; i < 7; ++i) w.f32(1);
    w.end(b);
    w.end(m);
    EXPECT_TRUE(failsWith(w.data, "submesh 0 ('M') has its own vertices but no M_GEOMETRY chunk follows (found M_MESH_BOUNDS (0x9000))"));

    // Uses shared vertices the mesh does not have.
    ChunkWriter v;
    v.header("[MeshSerializer_v1.8]");
    const auto m2 = v.begin(0x3000);
    v.boolean(false);
    const auto s2 = v.begin(0x4000);
    v.str("S");
    v.boolean(true);
    v.u32(0);
    v.boolean(false);
    v.end(s2);
    v.end(m2);
    EXPECT_TRUE(failsWith(v.data, "submesh 0 ('S') uses the shared vertices, but the mesh has none"));

    // An operation type the reader cannot turn into triangles (a tessellation patch).
    std::vector<std::uint8_t> p = smallMesh(Ogre::MESH_VERSION_LATEST);
    const ChunkRecord op = chunkOf(p, 0x4010);
    put16(p, op.offset + 6, 9);
    EXPECT_TRUE(failsWith(p, "operation type 9 is not supported"));

    // A second M_MESH.
    std::vector<std::uint8_t> two = smallMesh(Ogre::MESH_VERSION_1_8, Ogre::Serializer::ENDIAN_LITTLE, false);
    const ChunkRecord mesh = chunkOf(two, 0x3000);
    two.insert(two.end(), two.begin() + static_cast<std::ptrdiff_t>(mesh.offset), two.begin() + static_cast<std::ptrdiff_t>(mesh.end));
    EXPECT_TRUE(failsWith(two, "a second M_MESH chunk"));
}

// Every byte of small files flipped three ways: each read either succeeds or throws
// std::runtime_error (run under AddressSanitizer too, see README.md).
TEST(MeshMalformed, ByteDamageNeverCrashes) {
    const std::vector<std::vector<std::uint8_t>> files = {
        smallMesh(Ogre::MESH_VERSION_LATEST), smallMesh(Ogre::MESH_VERSION_1_8),
        smallMesh(Ogre::MESH_VERSION_1_7, Ogre::Serializer::ENDIAN_BIG), smallMesh(Ogre::MESH_VERSION_1_0)};
    int reads = 0, errors = 0;
    for (const auto& good : files)
        for (std::size_t i = 0; i < good.size(); ++i)
            for (const std::uint8_t damage : {std::uint8_t{0xFF}, std::uint8_t{0x80}, std::uint8_t{0x01}}) {
                std::vector<std::uint8_t> b = good;
                b[i] ^= damage;
                try {
                    const MeshFile m = readOgreMesh(b.data(), b.size(), "damaged.mesh");
                    // whatever it read is consistent
                    for (const auto& s : m.submeshes) {
                        ASSERT_EQ(s.indices.size() % 3, 0u);
                        for (std::uint32_t k : s.indices) ASSERT_LT(k, m.positionsOf(s).size());
                    }
                } catch (const std::runtime_error& e) {
                    ASSERT_EQ(std::string(e.what()).find("damaged.mesh: "), 0u) << e.what();
                    ++errors;
                }
                ++reads;
            }
    std::cout << reads << " damaged files, " << errors << " rejected\n";
    EXPECT_GT(errors, reads / 10);
}

TEST(MeshMalformed, FilesystemErrors) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("obscura-mesh-test-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    auto message = [](const std::string& path) -> std::string {
        try {
            readOgreMesh(path);
        } catch (const std::runtime_error& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_EQ(message(dir.string()), dir.string() + ": is a directory, not a .mesh file");
    EXPECT_EQ(message((dir / "missing.mesh").string()), (dir / "missing.mesh").string() + ": no such file");
    EXPECT_EQ(message("/dev/null"), "/dev/null: not a regular file");
    // Larger than the cap: refused from its size, before reading (a sparse file costs nothing).
    const fs::path big = dir / "huge.mesh";
    { std::ofstream(big.string()).put('\0'); }
    fs::resize_file(big, kMaxFileBytes + 1);
    EXPECT_EQ(message(big.string()), big.string() + ": 268435457 bytes, more than the reader's limit of 256 MiB");
    // A good file through the path API, and the same bytes cut short.
    const fs::path good = dir / "good.mesh";
    const std::vector<std::uint8_t> bytes = smallMesh(Ogre::MESH_VERSION_LATEST);
    {
        std::ofstream out(good.string(), std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    }
    EXPECT_EQ(readOgreMesh(good.string()).submeshes.size(), 2u);
    fs::resize_file(good, bytes.size() / 2);
    EXPECT_EQ(message(good.string()).find(good.string() + ": offset "), 0u);
    fs::remove_all(dir);
}
