// The reader against OGRE 1.12's own loader: the shared scenes, meshes built and written with
// OGRE's API in every version it can write (both byte orders), and hand-made v1.20 / v1.10 files.
#include "chunk_writer.h"
#include "mesh_compare.h"

#include <chrono>
#include <filesystem>
#include <iostream>

using namespace obscura;
using namespace obscura::mesh;
using namespace obscura::mesh::testing;

namespace {

const Ogre::MeshVersion kWritable[] = {Ogre::MESH_VERSION_LATEST, Ogre::MESH_VERSION_1_8, Ogre::MESH_VERSION_1_7,
                                       Ogre::MESH_VERSION_1_4, Ogre::MESH_VERSION_1_0};
const Ogre::Serializer::Endian kEndians[] = {Ogre::Serializer::ENDIAN_LITTLE, Ogre::Serializer::ENDIAN_BIG};

std::string sharedScene(const char* file) { return std::string(OBSCURA_THIRD_PARTY_DIR) + "/scenes/" + file; }

MeshFile readBuffer(const std::vector<std::uint8_t>& bytes, std::vector<ChunkRecord>* chunks = nullptr) {
    return readOgreMesh(bytes.data(), bytes.size(), "test.mesh", chunks);
}

void compareScene(const char* file, std::size_t submeshes) {
    const std::string path = sharedScene(file);
    const std::vector<std::uint8_t> bytes = readBytes(path);
    const MeshFile mine = readOgreMesh(path);
    const OgreMeshView ogre = loadWithOgre(bytes);
    EXPECT_EQ(mine.version, "[MeshSerializer_v1.100]");
    EXPECT_EQ(mine.submeshes.size(), submeshes);
    expectSameMesh(mine, ogre);
    std::size_t ogreTriangles = 0;
    for (const auto& s : ogre.subs) ogreTriangles += s.indices.size() / 3;
    EXPECT_EQ(mine.triangleCount(), ogreTriangles);
    std::vector<ChunkRecord> chunks;
    readBuffer(bytes, &chunks);
    EXPECT_TRUE(chunksEndWhereDeclared(chunks));
    std::cout << file << ": " << mine.submeshes.size() << " submeshes, " << mine.triangleCount() << " triangles, "
              << chunks.size() << " chunks\n";
}

// Overwrites every chunk length the reader does not need in a pre-v1.100 file (all but
// M_TABLE_EXTREMES), as OGRE before 1.10 could have written them wrong.
std::vector<std::uint8_t> scrambleLengths(std::vector<std::uint8_t> bytes, const std::vector<ChunkRecord>& chunks) {
    std::uint32_t garbage = 3;
    for (const ChunkRecord& c : chunks) {
        if (c.id == 0xE000) continue;
        std::memcpy(bytes.data() + c.offset + 2, &garbage, 4);
        garbage = garbage * 2654435761u + 12345u;
    }
    return bytes;
}

}  // namespace

TEST(MeshOgreReference, SibenikMatchesOgre) { compareScene("sibenik.mesh", 18); }

TEST(MeshOgreReference, CornellMatchesOgre) { compareScene("cornell.mesh", 1); }

TEST(MeshOgreReference, CornellIsTheBox) {
    const std::string path = sharedScene("cornell.mesh");
    const MeshFile m = readOgreMesh(path);
    ASSERT_EQ(m.submeshes.size(), 1u);
    EXPECT_EQ(m.submeshes[0].material, "BaseWhite");
    EXPECT_EQ(m.triangleCount(), 138u);
}

TEST(MeshOgreReference, SibenikReadsWellUnder100ms) {
    const std::string path = sharedScene("sibenik.mesh");
    double best = 1e9;
    for (int run = 0; run < 5; ++run) {
        const auto t0 = std::chrono::steady_clock::now();
        const MeshFile m = readOgreMesh(path);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        best = std::min(best, ms);
        ASSERT_GT(m.triangleCount(), 70000u);
    }
    std::cout << "sibenik.mesh read in " << best << " ms (best of 5)\n";
    RecordProperty("sibenik_read_ms", std::to_string(best));
#ifdef NDEBUG
    EXPECT_LT(best, 100.0);
#endif
}

// Every layout, vertex sharing and index size, in every version OGRE 1.12 writes, both byte orders.
TEST(MeshOgreWritten, EveryVersionLayoutAndByteOrder) {
    int files = 0;
    for (const Layout layout : {Layout::PositionOnly, Layout::Interleaved, Layout::SplitSources})
        for (int sharing = 0; sharing < 3; ++sharing)
            for (const bool idx32 : {false, true}) {
                MeshSpec spec;
                spec.layout = layout;
                spec.shared = sharing == 1;
                spec.mixed = sharing == 2;
                spec.indices32 = idx32;
                spec.submeshes = 3;
                spec.seed = static_cast<unsigned>(files + 1);
                const Ogre::MeshPtr mesh = buildMesh(spec);
                for (const Ogre::MeshVersion version : kWritable)
                    for (const auto endian : kEndians) {
                        SCOPED_TRACE(std::string(versionName(version)) + (endian == Ogre::Serializer::ENDIAN_BIG ? " big" : " little") +
                                     " layout " + std::to_string(static_cast<int>(layout)) + " sharing " + std::to_string(sharing) +
                                     (idx32 ? " 32-bit" : " 16-bit"));
                        const std::vector<std::uint8_t> bytes = writeWithOgre(*mesh, version, endian);
                        std::vector<ChunkRecord> chunks;
                        const MeshFile mine = readBuffer(bytes, &chunks);
                        EXPECT_EQ(mine.bigEndian, endian == Ogre::Serializer::ENDIAN_BIG);
                        expectSameMesh(mine, loadWithOgre(bytes));
                        EXPECT_TRUE(chunksEndWhereDeclared(chunks));
                        ++files;
                    }
                Ogre::MeshManager::getSingleton().remove(mesh);
            }
    EXPECT_EQ(files, 3 * 3 * 2 * 5 * 2);
}

// Strips and fans become lists (degenerate joins dropped), points and lines give no triangles,
// a submesh without indices draws its vertices in order.
TEST(MeshOgreWritten, OperationTypes) {
    using RO = Ogre::RenderOperation;
    for (const auto op : {RO::OT_TRIANGLE_STRIP, RO::OT_TRIANGLE_FAN, RO::OT_POINT_LIST, RO::OT_LINE_LIST,
                          RO::OT_LINE_STRIP, RO::OT_TRIANGLE_LIST})
        for (const bool indexed : {true, false})
            for (const bool shared : {false, true}) {
                MeshSpec spec;
                spec.operation = op;
                spec.indices = indexed ? 50 : 0;
                spec.shared = shared;
                const Ogre::MeshPtr mesh = buildMesh(spec);
                for (const Ogre::MeshVersion version : {Ogre::MESH_VERSION_LATEST, Ogre::MESH_VERSION_1_8})
                    for (const auto endian : kEndians) {
                        SCOPED_TRACE("operation " + std::to_string(op) + (indexed ? " indexed" : " non-indexed") +
                                     (shared ? " shared " : " own ") + versionName(version));
                        const std::vector<std::uint8_t> bytes = writeWithOgre(*mesh, version, endian);
                        const MeshFile mine = readBuffer(bytes);
                        expectSameMesh(mine, loadWithOgre(bytes));
                        const bool triangles = op == RO::OT_TRIANGLE_LIST || op == RO::OT_TRIANGLE_STRIP || op == RO::OT_TRIANGLE_FAN;
                        EXPECT_EQ(mine.triangleCount() > 0, triangles);
                    }
                Ogre::MeshManager::getSingleton().remove(mesh);
            }
}

TEST(MeshOgreWritten, StripWindingAndDegenerateJoins) {
    // The strip 0 1 2 3 3 4 4 5 6: triangles (0 1 2), (2 1 3), then joins, (4 5 6) flipped by parity.
    MeshSpec spec;
    spec.submeshes = 1;
    spec.vertices = 7;
    spec.operation = Ogre::RenderOperation::OT_TRIANGLE_STRIP;
    const Ogre::MeshPtr mesh = buildMesh(spec);
    const std::vector<std::uint32_t> strip = {0, 1, 2, 3, 3, 4, 4, 5, 6};
    Ogre::IndexData* id = mesh->getSubMesh(0)->indexData;
    std::vector<std::uint16_t> small(strip.begin(), strip.end());
    id->indexBuffer = Ogre::HardwareBufferManager::getSingleton().createIndexBuffer(
        Ogre::HardwareIndexBuffer::IT_16BIT, small.size(), Ogre::HardwareBuffer::HBU_STATIC, true);
    id->indexBuffer->writeData(0, small.size() * 2, small.data());
    id->indexCount = small.size();
    const MeshFile m = readBuffer(writeWithOgre(*mesh, Ogre::MESH_VERSION_LATEST));
    // t0 (0 1 2), t1 flipped (2 1 3), t2 (2 3 3) degenerate, t3 (3 3 4) degenerate, t4 (3 4 4)
    // degenerate, t5 flipped (4 4 5) degenerate, t6 (4 5 6), in that parity: even -> as is.
    EXPECT_EQ(m.submeshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3, 4, 5, 6}));
    Ogre::MeshManager::getSingleton().remove(mesh);
}

TEST(MeshOgreWritten, ThirtyTwoBitIndicesBeyondSixteenBits) {
    MeshSpec spec;
    spec.indices32 = true;
    spec.submeshes = 1;
    spec.vertices = 70000;
    spec.indices = 3000;
    spec.layout = Layout::SplitSources;
    const Ogre::MeshPtr mesh = buildMesh(spec);
    for (const auto endian : kEndians) {
        const std::vector<std::uint8_t> bytes = writeWithOgre(*mesh, Ogre::MESH_VERSION_LATEST, endian);
        const MeshFile mine = readBuffer(bytes);
        expectSameMesh(mine, loadWithOgre(bytes));
        std::uint32_t top = 0;
        for (std::uint32_t i : mine.submeshes[0].indices) top = std::max(top, i);
        EXPECT_GT(top, 65535u);
    }
    Ogre::MeshManager::getSingleton().remove(mesh);
}

// LODs, edge lists, poses, animations, name tables, extremes, bone assignments and texture
// aliases are stepped over, in every version's layout; the reader ends each chunk where the
// writer said it ends.
TEST(MeshOgreWritten, EverythingElseIsSteppedOver) {
    for (const Lod lod : {Lod::None, Lod::Generated, Lod::Manual})
        for (const bool edges : {false, true})
            for (const bool mixed : {false, true}) {
                MeshSpec spec;
                spec.mixed = mixed;
                spec.submeshes = 2;
                spec.seed = 40;
                Ogre::MeshPtr mesh = buildMesh(spec);
                addExtras(*mesh, lod, edges);
                for (const Ogre::MeshVersion version : kWritable)
                    for (const auto endian : kEndians) {
                        SCOPED_TRACE(std::string(versionName(version)) + " lod " + std::to_string(static_cast<int>(lod)) +
                                     (edges ? " edges" : "") + (mixed ? " mixed" : " own") +
                                     (endian == Ogre::Serializer::ENDIAN_BIG ? " big" : ""));
                        const std::vector<std::uint8_t> bytes = writeWithOgre(*mesh, version, endian);
                        std::vector<ChunkRecord> chunks;
                        const MeshFile mine = readBuffer(bytes, &chunks);
                        expectSameMesh(mine, loadWithOgre(bytes));
                        WriterQuirks quirks;
                        quirks.morphFlagUncounted = version == Ogre::MESH_VERSION_LATEST || version == Ogre::MESH_VERSION_1_8;
                        quirks.meshTotalUnreliable = true;
                        EXPECT_TRUE(chunksEndWhereDeclared(chunks, quirks));
                        EXPECT_GT(chunks.size(), 20u);
                    }
                Ogre::MeshManager::getSingleton().remove(mesh);
            }
}

// OGRE before 1.10 wrote wrong lengths for several chunks and never reads them; neither does the
// reader in files older than v1.100.
TEST(MeshOgreWritten, OlderVersionsIgnoreChunkLengths) {
    MeshSpec spec;
    spec.mixed = true;
    Ogre::MeshPtr mesh = buildMesh(spec);
    addExtras(*mesh, Lod::Generated, true);
    for (const Ogre::MeshVersion version : {Ogre::MESH_VERSION_1_8, Ogre::MESH_VERSION_1_7, Ogre::MESH_VERSION_1_4,
                                            Ogre::MESH_VERSION_1_0})
        for (const auto endian : kEndians) {
            SCOPED_TRACE(versionName(version));
            const std::vector<std::uint8_t> bytes = writeWithOgre(*mesh, version, endian);
            std::vector<ChunkRecord> chunks;
            const MeshFile original = readBuffer(bytes, &chunks);
            const std::vector<std::uint8_t> scrambled = scrambleLengths(bytes, chunks);
            const OgreMeshView ogre = loadWithOgre(scrambled);  // OGRE reads it as before
            expectSameMesh(original, ogre);
            expectSameMesh(readBuffer(scrambled), ogre);
        }
    // v1.100 lengths are trusted, so there the same damage is an error.
    const std::vector<std::uint8_t> bytes = writeWithOgre(*mesh, Ogre::MESH_VERSION_LATEST);
    std::vector<ChunkRecord> chunks;
    readBuffer(bytes, &chunks);
    EXPECT_THROW(readBuffer(scrambleLengths(bytes, chunks)), std::runtime_error);
    Ogre::MeshManager::getSingleton().remove(mesh);
}

// v1.20 and v1.10 (OGRE 1.0 and older): positions straight after the vertex count, normals,
// colours and texture coordinates in chunks of their own; v1.40-style LODs, v1.30-style edge
// lists, no normals in poses and morph keyframes.
namespace {
std::vector<std::uint8_t> legacyMesh(const std::string& version, bool big) {
    ChunkWriter w(big);
    w.header(version);
    const auto mesh = w.begin(0x3000);
    w.boolean(false);
    {
        const auto g = w.begin(0x5000);
        w.u32(4);
        const float p[4][3] = {{0, 0, 0}, {1.5f, 0, 0}, {0, 2.25f, -1}, {1e-3f, -7.125f, 3.3f}};
        for (const auto& v : p) w.f32(v[0]), w.f32(v[1]), w.f32(v[2]);
        const auto n = w.begin(0x5100);
        for (int i = 0; i < 12; ++i) w.f32(0.5f);
        w.end(n);
        const auto t = w.begin(0x5300);
        w.u16(2);
        for (int i = 0; i < 8; ++i) w.f32(0.25f * static_cast<float>(i));
        w.end(t);
        const auto c = w.begin(0x5200);
        for (int i = 0; i < 4; ++i) w.u32(0xFF00FF00u);
        w.end(c);
        w.end(g);
    }
    {
        const auto s = w.begin(0x4000);
        w.str("Legacy/Shared");
        w.boolean(true);
        w.u32(6);
        w.boolean(false);
        for (std::uint16_t i : {0, 1, 2, 2, 1, 3}) w.u16(i);
        const auto op = w.begin(0x4010);
        w.u16(4);
        w.end(op);
        w.end(s);
    }
    {
        const auto s = w.begin(0x4000);
        w.str("Legacy/Own");
        w.boolean(false);
        w.u32(5);
        w.boolean(true);
        for (std::uint32_t i : {0, 1, 2, 3, 4}) w.u32(i);
        const auto g = w.begin(0x5000);
        w.u32(5);
        for (int i = 0; i < 15; ++i) w.f32(static_cast<float>(i) * 0.1f - 0.7f);
        const auto t = w.begin(0x5300);
        w.u16(3);
        for (int i = 0; i < 15; ++i) w.f32(0.5f);
        w.end(t);
        w.end(g);
        const auto op = w.begin(0x4010);
        w.u16(5);  // a strip
        w.end(op);
        const auto ba = w.begin(0x4100);
        w.u32(0), w.u16(0), w.f32(1.0f);
        w.end(ba);
        w.end(s);
    }
    {
        const auto lod = w.begin(0x8000);  // v1.40 layout: no strategy name
        w.u16(2);
        w.boolean(true);
        const auto usage = w.begin(0x8100);
        w.f32(100.0f);
        const auto manual = w.begin(0x8110);
        w.str("far.mesh");
        w.end(manual);
        w.end(usage);
        w.end(lod);
    }
    {
        const auto b = w.begin(0x9000);
        for (float f : {0.0f, -7.125f, -1.0f, 1.5f, 2.25f, 3.3f, 8.0f}) w.f32(f);
        w.end(b);
    }
    {
        const auto table = w.begin(0xA000);
        const auto e = w.begin(0xA100);
        w.u16(0);
        w.str("the shared part");
        w.end(e);
        w.end(table);
    }
    {
        const auto lists = w.begin(0xB000);  // v1.30 layout: no isClosed, groups without triStart/Count
        const auto l = w.begin(0xB100);
        w.u16(0);
        w.boolean(false);
        w.u32(1);  // triangles
        w.u32(1);  // groups
        for (std::uint32_t v : {0u, 0u, 0u, 1u, 2u, 0u, 1u, 2u}) w.u32(v);
        for (float f : {0.0f, 0.0f, 1.0f, 0.0f}) w.f32(f);
        const auto g = w.begin(0xB110);
        w.u32(0);
        w.u32(1);  // edges
        for (std::uint32_t v : {0u, 0u, 0u, 1u, 0u, 1u}) w.u32(v);
        w.boolean(true);
        w.end(g);
        w.end(l);
        w.end(lists);
    }
    {
        const auto poses = w.begin(0xC000);
        const auto p = w.begin(0xC100);
        w.str("lift");
        w.u16(0);
        const auto v = w.begin(0xC111);
        w.u32(1), w.f32(0), w.f32(0.5f), w.f32(0);
        w.end(v);
        w.end(p);
        w.end(poses);
    }
    {
        const auto anims = w.begin(0xD000);
        const auto a = w.begin(0xD100);
        w.str("squash");
        w.f32(1.0f);
        const auto t = w.begin(0xD110);
        w.u16(1);  // morph
        w.u16(2);  // submesh 1's own vertices
        const auto k = w.begin(0xD111);
        w.f32(0.0f);
        for (int i = 0; i < 15; ++i) w.f32(1.0f);
        w.end(k);
        w.end(t);
        w.end(a);
        w.end(anims);
    }
    w.end(mesh);
    return w.data;
}
}  // namespace

TEST(MeshOgreLegacy, V120AndV110MatchOgre) {
    for (const char* version : {"[MeshSerializer_v1.20]", "[MeshSerializer_v1.10]"})
        for (const bool big : {false, true}) {
            SCOPED_TRACE(std::string(version) + (big ? " big" : " little"));
            const std::vector<std::uint8_t> bytes = legacyMesh(version, big);
            std::vector<ChunkRecord> chunks;
            const MeshFile mine = readBuffer(bytes, &chunks);
            const OgreMeshView ogre = loadWithOgre(bytes);
            expectSameMesh(mine, ogre);
            EXPECT_TRUE(chunksEndWhereDeclared(chunks));
            ASSERT_EQ(mine.submeshes.size(), 2u);
            EXPECT_EQ(mine.submeshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3}));
            EXPECT_EQ(mine.submeshes[1].operation, Operation::TriangleStrip);
            EXPECT_EQ(mine.submeshes[1].indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3, 2, 3, 4}));
            EXPECT_EQ(mine.sharedPositions[3], Vec3(1e-3f, -7.125f, 3.3f));
            // and with every length but the top-level one wrong, as OGRE of that era may have left them
            const std::vector<std::uint8_t> scrambled = scrambleLengths(bytes, chunks);
            expectSameMesh(readBuffer(scrambled), loadWithOgre(scrambled));
        }
}
