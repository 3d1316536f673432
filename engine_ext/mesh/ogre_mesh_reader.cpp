// See ogre_mesh_reader.h and README.md. The layout follows OGRE 1.12's MeshSerializerImpl and its
// per-version subclasses (OgreMain/src/OgreMeshSerializerImpl.cpp): the reader walks the chunks
// the way OGRE does, by their contents, because OGRE before 1.10 wrote wrong chunk lengths for
// several containers (M_MESH, M_SUBMESH, M_MESH_LOD_LEVEL, M_EDGE_LISTS, ...); OGRE itself
// never relies on them. Lengths are checked (and trusted) only in v1.100 files, which only the
// fixed writers produce, and where they are the only way on (top-level chunks we do not know,
// M_TABLE_EXTREMES).
#include "mesh/ogre_mesh_reader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <stdexcept>

namespace obscura::mesh {

namespace {

// Chunk ids (OgreMeshFileFormat.h).
constexpr std::uint16_t M_HEADER = 0x1000;
constexpr std::uint16_t M_MESH = 0x3000;
constexpr std::uint16_t M_SUBMESH = 0x4000;
constexpr std::uint16_t M_SUBMESH_OPERATION = 0x4010;
constexpr std::uint16_t M_SUBMESH_BONE_ASSIGNMENT = 0x4100;
constexpr std::uint16_t M_SUBMESH_TEXTURE_ALIAS = 0x4200;
constexpr std::uint16_t M_GEOMETRY = 0x5000;
constexpr std::uint16_t M_GEOMETRY_VERTEX_DECLARATION = 0x5100;
constexpr std::uint16_t M_GEOMETRY_VERTEX_ELEMENT = 0x5110;
constexpr std::uint16_t M_GEOMETRY_VERTEX_BUFFER = 0x5200;
constexpr std::uint16_t M_GEOMETRY_VERTEX_BUFFER_DATA = 0x5210;
// v1.20 / v1.10 geometry: the same first two ids with another meaning.
constexpr std::uint16_t M_GEOMETRY_NORMALS = 0x5100;
constexpr std::uint16_t M_GEOMETRY_COLOURS = 0x5200;
constexpr std::uint16_t M_GEOMETRY_TEXCOORDS = 0x5300;
constexpr std::uint16_t M_MESH_SKELETON_LINK = 0x6000;
constexpr std::uint16_t M_MESH_BONE_ASSIGNMENT = 0x7000;
constexpr std::uint16_t M_MESH_LOD_LEVEL = 0x8000;
constexpr std::uint16_t M_MESH_LOD_USAGE = 0x8100;
constexpr std::uint16_t M_MESH_LOD_MANUAL = 0x8110;
constexpr std::uint16_t M_MESH_LOD_GENERATED = 0x8120;
constexpr std::uint16_t M_MESH_BOUNDS = 0x9000;
constexpr std::uint16_t M_SUBMESH_NAME_TABLE = 0xA000;
constexpr std::uint16_t M_SUBMESH_NAME_TABLE_ELEMENT = 0xA100;
constexpr std::uint16_t M_EDGE_LISTS = 0xB000;
constexpr std::uint16_t M_EDGE_LIST_LOD = 0xB100;
constexpr std::uint16_t M_EDGE_GROUP = 0xB110;
constexpr std::uint16_t M_POSES = 0xC000;
constexpr std::uint16_t M_POSE = 0xC100;
constexpr std::uint16_t M_POSE_VERTEX = 0xC111;
constexpr std::uint16_t M_ANIMATIONS = 0xD000;
constexpr std::uint16_t M_ANIMATION = 0xD100;
constexpr std::uint16_t M_ANIMATION_BASEINFO = 0xD105;
constexpr std::uint16_t M_ANIMATION_TRACK = 0xD110;
constexpr std::uint16_t M_ANIMATION_MORPH_KEYFRAME = 0xD111;
constexpr std::uint16_t M_ANIMATION_POSE_KEYFRAME = 0xD112;
constexpr std::uint16_t M_ANIMATION_POSE_REF = 0xD113;
constexpr std::uint16_t M_TABLE_EXTREMES = 0xE000;

constexpr std::size_t kChunkHeader = 6;  // uint16 id + uint32 length
constexpr std::uint16_t VES_POSITION = 1;
constexpr std::uint16_t VET_FLOAT3 = 2;

// Oldest first, so "at least v1.8" is a comparison.
enum class Version { V1_10, V1_20, V1_30, V1_40, V1_41, V1_8, V1_100 };

std::string hex(std::uint32_t v, int digits = 4) {
    static const char* d = "0123456789abcdef";
    std::string s = "0x";
    for (int i = digits - 1; i >= 0; --i) s += d[(v >> (4 * i)) & 0xF];
    return s;
}

std::string chunkName(std::uint16_t id) {
    const char* n = nullptr;
    switch (id) {
    case M_HEADER: n = "M_HEADER"; break;
    case M_MESH: n = "M_MESH"; break;
    case M_SUBMESH: n = "M_SUBMESH"; break;
    case M_SUBMESH_OPERATION: n = "M_SUBMESH_OPERATION"; break;
    case M_SUBMESH_BONE_ASSIGNMENT: n = "M_SUBMESH_BONE_ASSIGNMENT"; break;
    case M_SUBMESH_TEXTURE_ALIAS: n = "M_SUBMESH_TEXTURE_ALIAS"; break;
    case M_GEOMETRY: n = "M_GEOMETRY"; break;
    case M_GEOMETRY_VERTEX_DECLARATION: n = "M_GEOMETRY_VERTEX_DECLARATION"; break;
    case M_GEOMETRY_VERTEX_ELEMENT: n = "M_GEOMETRY_VERTEX_ELEMENT"; break;
    case M_GEOMETRY_VERTEX_BUFFER: n = "M_GEOMETRY_VERTEX_BUFFER"; break;
    case M_GEOMETRY_VERTEX_BUFFER_DATA: n = "M_GEOMETRY_VERTEX_BUFFER_DATA"; break;
    case M_GEOMETRY_TEXCOORDS: n = "M_GEOMETRY_TEXCOORDS"; break;
    case M_MESH_SKELETON_LINK: n = "M_MESH_SKELETON_LINK"; break;
    case M_MESH_BONE_ASSIGNMENT: n = "M_MESH_BONE_ASSIGNMENT"; break;
    case M_MESH_LOD_LEVEL: n = "M_MESH_LOD_LEVEL"; break;
    case M_MESH_LOD_USAGE: n = "M_MESH_LOD_USAGE"; break;
    case M_MESH_LOD_MANUAL: n = "M_MESH_LOD_MANUAL"; break;
    case M_MESH_LOD_GENERATED: n = "M_MESH_LOD_GENERATED"; break;
    case M_MESH_BOUNDS: n = "M_MESH_BOUNDS"; break;
    case M_SUBMESH_NAME_TABLE: n = "M_SUBMESH_NAME_TABLE"; break;
    case M_SUBMESH_NAME_TABLE_ELEMENT: n = "M_SUBMESH_NAME_TABLE_ELEMENT"; break;
    case M_EDGE_LISTS: n = "M_EDGE_LISTS"; break;
    case M_EDGE_LIST_LOD: n = "M_EDGE_LIST_LOD"; break;
    case M_EDGE_GROUP: n = "M_EDGE_GROUP"; break;
    case M_POSES: n = "M_POSES"; break;
    case M_POSE: n = "M_POSE"; break;
    case M_POSE_VERTEX: n = "M_POSE_VERTEX"; break;
    case M_ANIMATIONS: n = "M_ANIMATIONS"; break;
    case M_ANIMATION: n = "M_ANIMATION"; break;
    case M_ANIMATION_BASEINFO: n = "M_ANIMATION_BASEINFO"; break;
    case M_ANIMATION_TRACK: n = "M_ANIMATION_TRACK"; break;
    case M_ANIMATION_MORPH_KEYFRAME: n = "M_ANIMATION_MORPH_KEYFRAME"; break;
    case M_ANIMATION_POSE_KEYFRAME: n = "M_ANIMATION_POSE_KEYFRAME"; break;
    case M_ANIMATION_POSE_REF: n = "M_ANIMATION_POSE_REF"; break;
    case M_TABLE_EXTREMES: n = "M_TABLE_EXTREMES"; break;
    default: break;
    }
    return n ? std::string(n) + " (" + hex(id) + ")" : "chunk " + hex(id);
}

// VertexElement::getTypeSize for VertexElementType 0..34 (0 for unknown types, as OGRE).
std::size_t vertexTypeSize(std::uint16_t type) {
    static const unsigned char sizes[] = {
        4, 8, 12, 16,    // FLOAT1..4
        4,               // COLOUR
        2, 4, 6, 8,      // SHORT1..4
        4,               // UBYTE4
        4, 4,            // COLOUR_ARGB, COLOUR_ABGR
        8, 16, 24, 32,   // DOUBLE1..4
        2, 4, 6, 8,      // USHORT1..4
        4, 8, 12, 16,    // INT1..4
        4, 8, 12, 16,    // UINT1..4
        4, 4, 4,         // BYTE4, BYTE4_NORM, UBYTE4_NORM
        4, 8, 4, 8,      // SHORT2_NORM, SHORT4_NORM, USHORT2_NORM, USHORT4_NORM
    };
    return type < sizeof(sizes) ? sizes[type] : 0;
}

struct Chunk {
    std::uint16_t id = 0;
    std::uint32_t length = 0;
    std::size_t offset = 0;
    std::size_t record = 0;  // index into the trace, when there is one
};

// A vertex data block as read: positions plus where it was, for messages.
struct Geometry {
    std::uint32_t vertexCount = 0;
    std::vector<Vec3> positions;
    std::size_t offset = 0;
};

struct RawSubMesh {
    MeshFile::SubMesh out;
    std::size_t offset = 0;
    std::vector<std::uint32_t> indices;  // as stored
    std::size_t indicesOffset = 0;
    bool indices32 = false;
    std::uint16_t operation = 4;
    std::size_t operationOffset = 0;
    Geometry geometry;  // own vertex data
};

class Reader {
public:
    Reader(const std::uint8_t* data, std::size_t size, const std::string& name, std::vector<ChunkRecord>* trace)
        : data_(data), size_(size), name_(name), trace_(trace) {}

    MeshFile read();

private:
    [[noreturn]] void fail(std::size_t offset, const std::string& what) const {
        throw std::runtime_error(name_ + ": offset " + std::to_string(offset) + ": " + what);
    }
    std::size_t left() const { return size_ - pos_; }
    void need(std::uint64_t bytes, const std::string& what) const {
        if (bytes > left())
            fail(pos_, "truncated: " + what + " needs " + std::to_string(bytes) + " bytes, " + std::to_string(left()) +
                           " left in the file");
    }
    void skip(std::uint64_t bytes, const std::string& what) {
        need(bytes, what);
        pos_ += static_cast<std::size_t>(bytes);
    }
    std::uint16_t u16(const char* what) {
        need(2, what);
        std::uint16_t v = static_cast<std::uint16_t>(data_[pos_] | (data_[pos_ + 1] << 8));
        if (swap_) v = static_cast<std::uint16_t>((v >> 8) | (v << 8));
        pos_ += 2;
        return v;
    }
    std::uint32_t u32(const char* what) {
        need(4, what);
        const std::uint32_t v = load32(pos_);
        pos_ += 4;
        return v;
    }
    float f32(const char* what) {
        const std::uint32_t bits = u32(what);
        float f;
        std::memcpy(&f, &bits, 4);
        return f;
    }
    bool boolean(const char* what) {
        need(1, what);
        return data_[pos_++] != 0;
    }
    std::uint32_t load32(std::size_t at) const {
        std::uint32_t v = static_cast<std::uint32_t>(data_[at]) | (static_cast<std::uint32_t>(data_[at + 1]) << 8) |
                          (static_cast<std::uint32_t>(data_[at + 2]) << 16) | (static_cast<std::uint32_t>(data_[at + 3]) << 24);
        if (swap_) v = (v >> 24) | ((v >> 8) & 0xFF00u) | ((v << 8) & 0xFF0000u) | (v << 24);
        return v;
    }
    float loadFloat(std::size_t at) const {
        const std::uint32_t bits = load32(at);
        float f;
        std::memcpy(&f, &bits, 4);
        return f;
    }
    // A '\n'-terminated string (a trailing '\r' dropped, as DataStream::getLine does).
    std::string str(const char* what, std::size_t maxBytes = static_cast<std::size_t>(-1)) {
        const std::size_t at = pos_;
        const std::size_t scan = std::min(left(), maxBytes);
        const void* nl = std::memchr(data_ + pos_, '\n', scan);
        if (!nl)
            fail(at, std::string("unterminated ") + what +
                         (scan < left() ? " (no newline in its first " + std::to_string(scan) + " bytes)"
                                        : std::string(" (no newline before the end of the file)")));
        std::size_t len = static_cast<const std::uint8_t*>(nl) - (data_ + pos_);
        pos_ += len + 1;
        if (len && data_[at + len - 1] == '\r') --len;
        if (std::memchr(data_ + at, '\0', len)) fail(at, std::string(what) + " contains a NUL byte");
        return std::string(reinterpret_cast<const char*>(data_ + at), len);
    }

    void checkLength(const Chunk& c) const {
        if (c.length < kChunkHeader)
            fail(c.offset, chunkName(c.id) + " declares length " + std::to_string(c.length) + ", less than its " +
                               std::to_string(kChunkHeader) + "-byte header");
        if (c.length > size_ - c.offset)
            fail(c.offset, chunkName(c.id) + " declares length " + std::to_string(c.length) +
                               ", which runs past the end of the file (" + std::to_string(size_ - c.offset) +
                               " bytes from its start)");
    }
    // Reads the chunk header at the current position.
    Chunk header() {
        Chunk c;
        c.offset = pos_;
        need(kChunkHeader, "chunk header");
        c.id = u16("chunk id");
        c.length = u32("chunk length");
        if (strictLengths_) checkLength(c);
        if (trace_) {
            c.record = trace_->size();
            trace_->push_back({c.id, depth_, c.offset, c.length, 0});
        }
        return c;
    }
    Chunk expect(std::uint16_t id, const char* context) {
        const Chunk c = header();
        if (c.id != id) fail(c.offset, std::string(context) + ": expected " + chunkName(id) + ", found " + chunkName(c.id));
        return c;
    }
    void close(const Chunk& c) {
        if (trace_) (*trace_)[c.record].end = pos_;
    }
    // The id of the next chunk, or nothing at the end of the file. OGRE's loops read a header,
    // carry on while its id is one they know, and step back over the first one they do not.
    std::optional<std::uint16_t> peek() {
        if (pos_ == size_) return std::nullopt;
        need(kChunkHeader, "chunk header");
        std::uint16_t v = static_cast<std::uint16_t>(data_[pos_] | (data_[pos_ + 1] << 8));
        if (swap_) v = static_cast<std::uint16_t>((v >> 8) | (v << 8));
        return v;
    }
    bool nextIs(std::initializer_list<std::uint16_t> ids) {
        const auto id = peek();
        if (!id) return false;
        for (std::uint16_t i : ids)
            if (*id == i) return true;
        return false;
    }
    struct Nest {
        explicit Nest(Reader& r) : r_(r) { ++r_.depth_; }
        ~Nest() { --r_.depth_; }
        Nest(const Nest&) = delete;
        Nest& operator=(const Nest&) = delete;
        Reader& r_;
    };

    void readMesh(const Chunk& mesh, MeshFile& out);
    Geometry readGeometry(const Chunk& c);
    Geometry readGeometryLegacy(const Chunk& c);
    RawSubMesh readSubMesh(const Chunk& c);
    void readLod(const Chunk& c);
    void readEdgeLists(const Chunk& c);
    void readPoses(const Chunk& c);
    void readAnimations(const Chunk& c);
    std::uint32_t trackVertexCount(std::uint16_t target, std::size_t at) const;
    void finishSubMesh(RawSubMesh& s, std::size_t index, const Geometry* shared);

    const std::uint8_t* data_;
    std::size_t size_;
    std::string name_;
    std::vector<ChunkRecord>* trace_;
    std::size_t pos_ = 0;
    bool swap_ = false;
    bool strictLengths_ = false;
    Version version_ = Version::V1_100;
    int depth_ = 0;
    std::size_t totalIndices_ = 0;  // of the triangle lists made so far
    // What later chunks refer to while the mesh is read.
    std::optional<Geometry> shared_;
    std::vector<RawSubMesh> subs_;
};

MeshFile Reader::read() {
    MeshFile out;
    if (size_ < 2) fail(0, "too short for an OGRE mesh (" + std::to_string(size_) + " bytes)");
    const std::uint16_t raw = static_cast<std::uint16_t>(data_[0] | (data_[1] << 8));
    if (raw == M_HEADER) {
        swap_ = false;
    } else if (raw == 0x0010) {
        swap_ = true;
    } else {
        fail(0, "not an OGRE .mesh file: header id " + hex(raw) + " (expected " + hex(M_HEADER) + " in either byte order)");
    }
    out.bigEndian = swap_;
    pos_ = 2;
    out.version = str("version string", 64);
    static const struct {
        const char* text;
        Version version;
    } versions[] = {
        {"[MeshSerializer_v1.100]", Version::V1_100}, {"[MeshSerializer_v1.8]", Version::V1_8},
        {"[MeshSerializer_v1.41]", Version::V1_41},   {"[MeshSerializer_v1.40]", Version::V1_40},
        {"[MeshSerializer_v1.30]", Version::V1_30},   {"[MeshSerializer_v1.20]", Version::V1_20},
        {"[MeshSerializer_v1.10]", Version::V1_10},
    };
    bool known = false;
    for (const auto& v : versions)
        if (out.version == v.text) {
            version_ = v.version;
            known = true;
        }
    if (!known)
        fail(2, "unsupported mesh version '" + out.version +
                    "' (this reader knows OGRE 1.x's [MeshSerializer_v1.10] .. [MeshSerializer_v1.100])");
    strictLengths_ = version_ == Version::V1_100;

    bool seenMesh = false;
    while (pos_ < size_) {
        const Chunk c = header();
        if (c.id == M_MESH) {
            if (seenMesh) fail(c.offset, "a second M_MESH chunk");
            seenMesh = true;
            readMesh(c, out);
        } else {
            // Not part of any mesh this reader knows: step over it by its length.
            checkLength(c);
            pos_ = c.offset + c.length;
            close(c);
        }
    }
    if (!seenMesh) fail(pos_, "no M_MESH chunk in the file");
    return out;
}

void Reader::readMesh(const Chunk& mesh, MeshFile& out) {
    Nest nest(*this);
    boolean("M_MESH skeletallyAnimated flag");
    bool inMesh = true;
    while (inMesh) {
        const auto id = peek();
        if (!id) break;
        switch (*id) {
        case M_GEOMETRY: {
            const Chunk c = header();
            if (shared_) fail(c.offset, "a second shared M_GEOMETRY in the mesh");
            shared_ = version_ >= Version::V1_30 ? readGeometry(c) : readGeometryLegacy(c);
            close(c);
            break;
        }
        case M_SUBMESH: {
            const Chunk c = header();
            subs_.push_back(readSubMesh(c));
            close(c);
            break;
        }
        case M_MESH_SKELETON_LINK: {
            const Chunk c = header();
            str("skeleton name");
            close(c);
            break;
        }
        case M_MESH_BONE_ASSIGNMENT: {
            const Chunk c = header();
            skip(10, "M_MESH_BONE_ASSIGNMENT");  // uint32 vertex, uint16 bone, float weight
            close(c);
            break;
        }
        case M_MESH_LOD_LEVEL: {
            const Chunk c = header();
            readLod(c);
            close(c);
            break;
        }
        case M_MESH_BOUNDS: {
            const Chunk c = header();
            MeshFile::Bounds b;
            b.min.x = f32("bounds");
            b.min.y = f32("bounds");
            b.min.z = f32("bounds");
            b.max.x = f32("bounds");
            b.max.y = f32("bounds");
            b.max.z = f32("bounds");
            b.radius = f32("bounding radius");
            out.bounds = b;
            close(c);
            break;
        }
        case M_SUBMESH_NAME_TABLE: {
            const Chunk c = header();
            Nest inner(*this);
            while (nextIs({M_SUBMESH_NAME_TABLE_ELEMENT})) {
                const Chunk e = header();
                u16("submesh index");
                str("submesh name");
                close(e);
            }
            close(c);
            break;
        }
        case M_EDGE_LISTS: {
            const Chunk c = header();
            readEdgeLists(c);
            close(c);
            break;
        }
        case M_POSES: {
            const Chunk c = header();
            readPoses(c);
            close(c);
            break;
        }
        case M_ANIMATIONS: {
            const Chunk c = header();
            readAnimations(c);
            close(c);
            break;
        }
        case M_TABLE_EXTREMES: {
            // uint16 submesh index, then floats to the end of the chunk: the length is the only
            // way to know how many (OGRE reads it the same way).
            const Chunk c = header();
            checkLength(c);
            if (c.length < kChunkHeader + 2) fail(c.offset, "M_TABLE_EXTREMES shorter than its submesh index");
            pos_ = c.offset + c.length;
            close(c);
            break;
        }
        default:
            // Not a mesh child: the mesh ends here (OGRE steps back and returns to the top level).
            inMesh = false;
            break;
        }
    }
    close(mesh);

    const Geometry* shared = shared_ ? &*shared_ : nullptr;
    if (shared) out.sharedPositions = std::move(shared_->positions);
    out.submeshes.reserve(subs_.size());
    for (std::size_t i = 0; i < subs_.size(); ++i) {
        finishSubMesh(subs_[i], i, shared);
        out.submeshes.push_back(std::move(subs_[i].out));
    }
    subs_.clear();
}

RawSubMesh Reader::readSubMesh(const Chunk& c) {
    Nest nest(*this);
    RawSubMesh s;
    s.offset = c.offset;
    s.out.material = str("submesh material name");
    s.out.sharedVertices = boolean("submesh useSharedVertices flag");
    const std::size_t countAt = pos_;
    const std::uint32_t indexCount = u32("submesh index count");
    s.indices32 = boolean("submesh indexes32Bit flag");
    if (indexCount > kMaxIndices)
        fail(countAt, "submesh index count " + std::to_string(indexCount) + " exceeds the reader's limit of " +
                          std::to_string(kMaxIndices));
    s.indicesOffset = pos_;
    const std::size_t indexSize = s.indices32 ? 4 : 2;
    need(std::uint64_t{indexCount} * indexSize, "submesh index data (" + std::to_string(indexCount) + " indices)");
    s.indices.resize(indexCount);
    if (s.indices32) {
        for (std::uint32_t i = 0; i < indexCount; ++i) s.indices[i] = load32(pos_ + std::size_t{i} * 4);
    } else {
        for (std::uint32_t i = 0; i < indexCount; ++i) {
            const std::size_t at = pos_ + std::size_t{i} * 2;
            std::uint16_t v = static_cast<std::uint16_t>(data_[at] | (data_[at + 1] << 8));
            if (swap_) v = static_cast<std::uint16_t>((v >> 8) | (v << 8));
            s.indices[i] = v;
        }
    }
    pos_ += std::size_t{indexCount} * indexSize;

    if (!s.out.sharedVertices) {
        const auto id = peek();
        if (!id || *id != M_GEOMETRY)
            fail(pos_, "submesh " + std::to_string(subs_.size()) + " ('" + s.out.material +
                           "') has its own vertices but no M_GEOMETRY chunk follows" +
                           (id ? " (found " + chunkName(*id) + ")" : std::string(" (end of file)")));
        const Chunk g = header();
        s.geometry = version_ >= Version::V1_30 ? readGeometry(g) : readGeometryLegacy(g);
        close(g);
    }
    while (nextIs({M_SUBMESH_OPERATION, M_SUBMESH_BONE_ASSIGNMENT, M_SUBMESH_TEXTURE_ALIAS})) {
        const Chunk k = header();
        if (k.id == M_SUBMESH_OPERATION) {
            s.operationOffset = pos_;
            s.operation = u16("submesh operation type");
        } else if (k.id == M_SUBMESH_BONE_ASSIGNMENT) {
            skip(10, "M_SUBMESH_BONE_ASSIGNMENT");
        } else {
            str("texture alias name");
            str("texture name");
        }
        close(k);
    }
    return s;
}

Geometry Reader::readGeometry(const Chunk& c) {
    Nest nest(*this);
    Geometry g;
    g.offset = c.offset;
    const std::size_t countAt = pos_;
    g.vertexCount = u32("vertex count");
    if (g.vertexCount > kMaxVertices)
        fail(countAt, "vertex count " + std::to_string(g.vertexCount) + " exceeds the reader's limit of " +
                          std::to_string(kMaxVertices));
    struct Element {
        std::uint16_t source, type, semantic, offset;
        std::size_t at;
    };
    struct Buffer {
        std::uint16_t bind, vertexSize;
        std::size_t data;
    };
    std::vector<Element> elements;
    std::vector<Buffer> buffers;
    while (nextIs({M_GEOMETRY_VERTEX_DECLARATION, M_GEOMETRY_VERTEX_BUFFER})) {
        const Chunk k = header();
        if (k.id == M_GEOMETRY_VERTEX_DECLARATION) {
            Nest inner(*this);
            while (nextIs({M_GEOMETRY_VERTEX_ELEMENT})) {
                const Chunk e = header();
                Element el;
                el.at = pos_;
                el.source = u16("vertex element source");
                el.type = u16("vertex element type");
                el.semantic = u16("vertex element semantic");
                el.offset = u16("vertex element offset");
                u16("vertex element index");
                elements.push_back(el);
                close(e);
            }
        } else {
            Nest inner(*this);
            const std::size_t bindAt = pos_;
            Buffer b;
            b.bind = u16("vertex buffer bind index");
            b.vertexSize = u16("vertex buffer vertex size");
            const Chunk d = expect(M_GEOMETRY_VERTEX_BUFFER_DATA, "vertex buffer");
            std::size_t declared = 0;
            for (const Element& e : elements)
                if (e.source == b.bind) declared += vertexTypeSize(e.type);
            if (declared != b.vertexSize)
                fail(bindAt, "vertex buffer for source " + std::to_string(b.bind) + " has vertex size " +
                                 std::to_string(b.vertexSize) + " but its declared elements add up to " +
                                 std::to_string(declared));
            for (const Buffer& o : buffers)
                if (o.bind == b.bind) fail(bindAt, "a second vertex buffer for source " + std::to_string(b.bind));
            b.data = pos_;
            skip(std::uint64_t{g.vertexCount} * b.vertexSize,
                 "vertex buffer data (" + std::to_string(g.vertexCount) + " vertices of " +
                     std::to_string(b.vertexSize) + " bytes)");
            buffers.push_back(b);
            close(d);
        }
        close(k);
    }

    const Element* pos = nullptr;
    for (const Element& e : elements)
        if (e.semantic == VES_POSITION) {
            pos = &e;
            break;
        }
    if (!pos) {
        if (g.vertexCount == 0) return g;
        fail(c.offset, "vertex data of " + std::to_string(g.vertexCount) + " vertices has no position element");
    }
    if (pos->type != VET_FLOAT3)
        fail(pos->at, "position element has vertex type " + std::to_string(pos->type) +
                          "; only float3 positions (VET_FLOAT3 = 2) are supported");
    const Buffer* buf = nullptr;
    for (const Buffer& b : buffers)
        if (b.bind == pos->source) buf = &b;
    if (!buf) {
        if (g.vertexCount == 0) return g;
        fail(c.offset, "no vertex buffer is bound to the position element's source " + std::to_string(pos->source));
    }
    if (std::size_t{pos->offset} + 12 > buf->vertexSize)
        fail(pos->at, "position element at offset " + std::to_string(pos->offset) +
                          " does not fit in its buffer's vertex size " + std::to_string(buf->vertexSize));
    g.positions.resize(g.vertexCount);
    std::size_t at = buf->data + pos->offset;
    for (std::uint32_t i = 0; i < g.vertexCount; ++i, at += buf->vertexSize)
        g.positions[i] = {loadFloat(at), loadFloat(at + 4), loadFloat(at + 8)};
    return g;
}

// v1.20 / v1.10: positions right after the count, then optional normal, colour and texture
// coordinate chunks, one buffer each.
Geometry Reader::readGeometryLegacy(const Chunk& c) {
    Nest nest(*this);
    Geometry g;
    g.offset = c.offset;
    const std::size_t countAt = pos_;
    g.vertexCount = u32("vertex count");
    if (g.vertexCount > kMaxVertices)
        fail(countAt, "vertex count " + std::to_string(g.vertexCount) + " exceeds the reader's limit of " +
                          std::to_string(kMaxVertices));
    need(std::uint64_t{g.vertexCount} * 12, "positions (" + std::to_string(g.vertexCount) + " vertices)");
    g.positions.resize(g.vertexCount);
    for (std::uint32_t i = 0; i < g.vertexCount; ++i, pos_ += 12)
        g.positions[i] = {loadFloat(pos_), loadFloat(pos_ + 4), loadFloat(pos_ + 8)};
    while (nextIs({M_GEOMETRY_NORMALS, M_GEOMETRY_COLOURS, M_GEOMETRY_TEXCOORDS})) {
        const Chunk k = header();
        if (k.id == M_GEOMETRY_NORMALS) {
            skip(std::uint64_t{g.vertexCount} * 12, "normals");
        } else if (k.id == M_GEOMETRY_COLOURS) {
            skip(std::uint64_t{g.vertexCount} * 4, "colours");
        } else {
            const std::size_t dimAt = pos_;
            const std::uint16_t dim = u16("texture coordinate dimensions");
            if (dim < 1 || dim > 4) fail(dimAt, "texture coordinates with " + std::to_string(dim) + " dimensions");
            skip(std::uint64_t{g.vertexCount} * dim * 4, "texture coordinates");
        }
        close(k);
    }
    return g;
}

// LOD levels: read only to step over them; three layouts (v1.100, v1.8/v1.41, v1.40 and older).
void Reader::readLod(const Chunk&) {
    Nest nest(*this);
    const std::size_t numSubs = subs_.size();
    if (version_ >= Version::V1_41) str("LOD strategy name");
    const std::uint16_t numLods = u16("LOD level count");
    if (version_ == Version::V1_100) {
        for (unsigned lod = 1; lod < numLods; ++lod) {
            const Chunk u = header();
            if (u.id != M_MESH_LOD_MANUAL && u.id != M_MESH_LOD_GENERATED)
                fail(u.offset, "LOD level " + std::to_string(lod) + ": expected M_MESH_LOD_MANUAL or M_MESH_LOD_GENERATED, found " +
                                   chunkName(u.id));
            f32("LOD value");
            if (u.id == M_MESH_LOD_MANUAL) {
                str("manual LOD mesh name");
            } else {
                for (std::size_t i = 0; i < numSubs; ++i) {
                    u32("LOD index count");
                    u32("LOD index start");
                    const std::uint32_t bufferIndex = u32("LOD buffer index");
                    if (bufferIndex == 0xFFFFFFFFu) {
                        const bool idx32 = boolean("LOD indexes32Bit flag");
                        const std::uint32_t count = u32("LOD buffer index count");
                        skip(std::uint64_t{count} * (idx32 ? 4 : 2), "LOD index buffer");
                    }
                }
            }
            close(u);
        }
        return;
    }
    const bool manual = boolean("LOD manual flag");
    for (unsigned lod = 1; lod < numLods; ++lod) {
        const Chunk u = expect(M_MESH_LOD_USAGE, "LOD level");
        Nest inner(*this);
        f32("LOD value");
        if (manual) {
            const Chunk m = expect(M_MESH_LOD_MANUAL, "manual LOD level");
            str("manual LOD mesh name");
            close(m);
        } else {
            for (std::size_t i = 0; i < numSubs; ++i) {
                const Chunk g = expect(M_MESH_LOD_GENERATED, "generated LOD level");
                const std::uint32_t count = u32("LOD index count");
                const bool idx32 = boolean("LOD indexes32Bit flag");
                skip(std::uint64_t{count} * (idx32 ? 4 : 2), "LOD index buffer");
                close(g);
            }
        }
        close(u);
    }
}

void Reader::readEdgeLists(const Chunk&) {
    Nest nest(*this);
    const bool closedFlag = version_ >= Version::V1_40;  // v1.30 and older: no isClosed, shorter groups
    while (nextIs({M_EDGE_LIST_LOD})) {
        const Chunk l = header();
        Nest inner(*this);
        u16("edge list LOD index");
        const bool isManual = boolean("edge list manual flag");
        if (!isManual) {
            if (closedFlag) boolean("edge list closed flag");
            const std::uint32_t triangles = u32("edge list triangle count");
            const std::uint32_t groups = u32("edge group count");
            // per triangle: uint32 indexSet, vertexSet, vertIndex[3], sharedVertIndex[3]; float normal[4]
            skip(std::uint64_t{triangles} * 48, "edge list triangles");
            for (std::uint32_t i = 0; i < groups; ++i) {
                const Chunk e = expect(M_EDGE_GROUP, "edge list");
                skip(closedFlag ? 12 : 4, "edge group header");  // vertexSet [, triStart, triCount]
                const std::uint32_t edges = u32("edge count");
                // per edge: uint32 triIndex[2], vertIndex[2], sharedVertIndex[2]; bool degenerate
                skip(std::uint64_t{edges} * 25, "edges");
                close(e);
            }
        }
        close(l);
    }
}

void Reader::readPoses(const Chunk&) {
    Nest nest(*this);
    const bool normalsFlag = version_ >= Version::V1_8;
    while (nextIs({M_POSE})) {
        const Chunk p = header();
        Nest inner(*this);
        str("pose name");
        u16("pose target");
        const bool normals = normalsFlag && boolean("pose includesNormals flag");
        while (nextIs({M_POSE_VERTEX})) {
            const Chunk v = header();
            skip(normals ? 28 : 16, "pose vertex");  // uint32 index, float offset[3] [, normal[3]]
            close(v);
        }
        close(p);
    }
}

std::uint32_t Reader::trackVertexCount(std::uint16_t target, std::size_t at) const {
    if (target == 0) {
        if (!shared_) fail(at, "morph keyframe for the shared vertices, but the mesh has none");
        return shared_->vertexCount;
    }
    if (target > subs_.size() || subs_[target - 1].out.sharedVertices)
        fail(at, "morph keyframe for submesh " + std::to_string(target - 1) + ", which has no vertex data of its own");
    return subs_[target - 1].geometry.vertexCount;
}

void Reader::readAnimations(const Chunk&) {
    Nest nest(*this);
    const bool normalsFlag = version_ >= Version::V1_8;
    while (nextIs({M_ANIMATION})) {
        const Chunk a = header();
        Nest inAnimation(*this);
        str("animation name");
        f32("animation length");
        if (nextIs({M_ANIMATION_BASEINFO})) {
            const Chunk b = header();
            str("base animation name");
            f32("base keyframe time");
            close(b);
        }
        while (nextIs({M_ANIMATION_TRACK})) {
            const Chunk t = header();
            Nest inTrack(*this);
            u16("animation track type");
            const std::uint16_t target = u16("animation track target");
            while (nextIs({M_ANIMATION_MORPH_KEYFRAME, M_ANIMATION_POSE_KEYFRAME})) {
                const Chunk k = header();
                f32("keyframe time");
                if (k.id == M_ANIMATION_MORPH_KEYFRAME) {
                    const bool normals = normalsFlag && boolean("morph keyframe includesNormals flag");
                    const std::uint32_t vertices = trackVertexCount(target, k.offset);
                    skip(std::uint64_t{vertices} * (normals ? 24 : 12), "morph keyframe vertices");
                } else {
                    Nest inKey(*this);
                    while (nextIs({M_ANIMATION_POSE_REF})) {
                        const Chunk r = header();
                        skip(6, "pose reference");  // uint16 pose index, float influence
                        close(r);
                    }
                }
                close(k);
            }
            close(t);
        }
        close(a);
    }
}

void Reader::finishSubMesh(RawSubMesh& s, std::size_t index, const Geometry* shared) {
    const std::string which = "submesh " + std::to_string(index) + " ('" + s.out.material + "')";
    std::uint32_t vertexCount;
    if (s.out.sharedVertices) {
        if (!shared) fail(s.offset, which + " uses the shared vertices, but the mesh has none");
        vertexCount = shared->vertexCount;
    } else {
        vertexCount = s.geometry.vertexCount;
        s.out.positions = std::move(s.geometry.positions);
    }
    const std::size_t indexSize = s.indices32 ? 4 : 2;
    for (std::size_t i = 0; i < s.indices.size(); ++i)
        if (s.indices[i] >= vertexCount)
            fail(s.indicesOffset + i * indexSize, which + ": index " + std::to_string(s.indices[i]) +
                                                      " out of range (" + std::to_string(vertexCount) + " vertices)");
    // No indices: OGRE draws the vertices in order.
    const bool implicit = s.indices.empty();
    const std::size_t n = implicit ? vertexCount : s.indices.size();
    auto at = [&](std::size_t k) { return implicit ? static_cast<std::uint32_t>(k) : s.indices[k]; };
    std::size_t most = 0;  // triangle-list indices this submesh can give
    switch (s.operation) {
    case 1:
    case 2:
    case 3: break;                                // points and lines: no triangles
    case 4: most = n / 3 * 3; break;              // a list; an incomplete last triangle is dropped
    case 5:                                       // strips and fans: a triangle per index after two
    case 6: most = n >= 3 ? 3 * (n - 2) : 0; break;
    default:
        fail(s.operationOffset, which + ": operation type " + std::to_string(s.operation) +
                                    " is not supported (points, lines, triangle lists, strips and fans are)");
    }
    if (most > kMaxIndices - totalIndices_)
        fail(s.offset, which + " would bring the mesh's triangle list past the reader's limit of " +
                           std::to_string(kMaxIndices) + " indices");
    std::vector<std::uint32_t>& out = s.out.indices;
    out.reserve(most);
    if (s.operation == 4) {
        for (std::size_t k = 0; k < most; ++k) out.push_back(at(k));
    } else if (s.operation == 5) {
        // every other triangle flipped to keep the winding; degenerate joins dropped
        for (std::size_t i = 0; i + 2 < n; ++i) {
            const std::uint32_t a = at(i + (i & 1)), b = at(i + 1 - (i & 1)), c = at(i + 2);
            if (a != b && b != c && a != c) out.insert(out.end(), {a, b, c});
        }
    } else if (s.operation == 6) {
        // a fan around the first vertex
        for (std::size_t i = 1; i + 1 < n; ++i) {
            const std::uint32_t a = at(0), b = at(i), c = at(i + 1);
            if (a != b && b != c && a != c) out.insert(out.end(), {a, b, c});
        }
    }
    totalIndices_ += out.size();
    s.out.operation = static_cast<Operation>(s.operation);
    std::vector<std::uint32_t>().swap(s.indices);
}

// OGRE 1.12's single-precision path, step for step: Quaternion::FromAngleAxis,
// Quaternion::ToRotationMatrix, TransformBaseReal::makeTransform, operator*(Affine3, Vector3).
struct Affine {
    float m[3][4];
};

Affine makeAffine(const Transform& t) {
    const float yaw = static_cast<float>(t.yaw);
    const float s = static_cast<float>(t.scale);
    const float half = 0.5f * yaw;
    const float sn = std::sin(half);
    const float w = std::cos(half);
    const float x = sn * 0.0f, y = sn * 1.0f, z = sn * 0.0f;  // axis UNIT_Y, signs of zero as OGRE's
    const float tx = x + x, ty = y + y, tz = z + z;
    const float twx = tx * w, twy = ty * w, twz = tz * w;
    const float txx = tx * x, txy = ty * x, txz = tz * x;
    const float tyy = ty * y, tyz = tz * y, tzz = tz * z;
    const float r[3][3] = {{1.0f - (tyy + tzz), txy - twz, txz + twy},
                           {txy + twz, 1.0f - (txx + tzz), tyz - twx},
                           {txz - twy, tyz + twx, 1.0f - (txx + tyy)}};
    const float origin[3] = {static_cast<float>(t.origin.x), static_cast<float>(t.origin.y),
                             static_cast<float>(t.origin.z)};
    Affine a;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) a.m[i][j] = s * r[i][j];
        a.m[i][3] = origin[i];
    }
    return a;
}

Vec3 apply(const Affine& a, const Vec3& p) {
    const float x = static_cast<float>(p.x), y = static_cast<float>(p.y), z = static_cast<float>(p.z);
    const float rx = a.m[0][0] * x + a.m[0][1] * y + a.m[0][2] * z + a.m[0][3];
    const float ry = a.m[1][0] * x + a.m[1][1] * y + a.m[1][2] * z + a.m[1][3];
    const float rz = a.m[2][0] * x + a.m[2][1] * y + a.m[2][2] * z + a.m[2][3];
    return {rx, ry, rz};
}

}  // namespace

std::size_t MeshFile::triangleCount() const {
    std::size_t n = 0;
    for (const SubMesh& s : submeshes) n += s.indices.size() / 3;
    return n;
}

MeshFile readOgreMesh(const void* data, std::size_t size, const std::string& name, std::vector<ChunkRecord>* chunks) {
    if (size > kMaxFileBytes)
        throw std::runtime_error(name + ": " + std::to_string(size) + " bytes, more than the reader's limit of " +
                                 std::to_string(kMaxFileBytes >> 20) + " MiB");
    if (chunks) chunks->clear();
    return Reader(static_cast<const std::uint8_t*>(data), size, name, chunks).read();
}

MeshFile readOgreMesh(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (st.type() == fs::file_type::not_found) throw std::runtime_error(path + ": no such file");
    if (ec) throw std::runtime_error(path + ": " + ec.message());
    if (fs::is_directory(st)) throw std::runtime_error(path + ": is a directory, not a .mesh file");
    if (!fs::is_regular_file(st)) throw std::runtime_error(path + ": not a regular file");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw std::runtime_error(path + ": cannot read its size: " + ec.message());
    if (size > kMaxFileBytes)
        throw std::runtime_error(path + ": " + std::to_string(size) + " bytes, more than the reader's limit of " +
                                 std::to_string(kMaxFileBytes >> 20) + " MiB");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open");
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (static_cast<std::uintmax_t>(in.gcount()) != size) throw std::runtime_error(path + ": read failed");
    return readOgreMesh(bytes.data(), bytes.size(), path);
}

Vec3 transformPoint(const Transform& transform, const Vec3& point) { return apply(makeAffine(transform), point); }

TriangleMesh meshTriangles(const MeshFile& mesh, const Transform& transform) {
    const Affine a = makeAffine(transform);
    TriangleMesh out;
    std::size_t vertices = 0, indices = 0;
    bool sharedUsed = false;
    for (const auto& s : mesh.submeshes) {
        if (s.indices.empty()) continue;
        indices += s.indices.size();
        if (s.sharedVertices)
            sharedUsed = true;
        else
            vertices += s.positions.size();
    }
    if (sharedUsed) vertices += mesh.sharedPositions.size();
    out.vertices.reserve(vertices);
    out.indices.reserve(indices);
    std::optional<std::uint32_t> sharedBase;
    for (const auto& s : mesh.submeshes) {
        if (s.indices.empty()) continue;
        std::uint32_t base;
        if (s.sharedVertices && sharedBase) {
            base = *sharedBase;
        } else {
            base = static_cast<std::uint32_t>(out.vertices.size());
            if (s.sharedVertices) sharedBase = base;
            for (const Vec3& p : mesh.positionsOf(s)) out.vertices.push_back(apply(a, p));
        }
        for (std::uint32_t i : s.indices) out.indices.push_back(base + i);
    }
    return out;
}

}  // namespace obscura::mesh
