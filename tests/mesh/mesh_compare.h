// Comparing the reader's MeshFile with what OGRE's own loader made of the same bytes.
#pragma once

#include "mesh/ogre_mesh_reader.h"
#include "ogre_helpers.h"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

namespace obscura::mesh::testing {

// Exact: every coordinate is a float in the file, and a double holds it unchanged.
inline ::testing::AssertionResult samePositions(const std::vector<Vec3>& mine, const std::vector<float>& ogre) {
    if (mine.size() * 3 != ogre.size())
        return ::testing::AssertionFailure() << mine.size() << " vertices, OGRE has " << ogre.size() / 3;
    for (size_t i = 0; i < mine.size(); ++i) {
        const Vec3& p = mine[i];
        if (p.x != ogre[3 * i] || p.y != ogre[3 * i + 1] || p.z != ogre[3 * i + 2])
            return ::testing::AssertionFailure() << "vertex " << i << ": (" << p.x << ", " << p.y << ", " << p.z
                                                 << ") vs OGRE (" << ogre[3 * i] << ", " << ogre[3 * i + 1] << ", "
                                                 << ogre[3 * i + 2] << ")";
    }
    return ::testing::AssertionSuccess();
}

inline ::testing::AssertionResult sameIndices(const std::vector<std::uint32_t>& mine, const std::vector<std::uint32_t>& expected) {
    if (mine.size() != expected.size())
        return ::testing::AssertionFailure() << mine.size() << " indices, expected " << expected.size();
    for (size_t i = 0; i < mine.size(); ++i)
        if (mine[i] != expected[i])
            return ::testing::AssertionFailure() << "index " << i << ": " << mine[i] << ", expected " << expected[i];
    return ::testing::AssertionSuccess();
}

inline void expectSameMesh(const MeshFile& mine, const OgreMeshView& ogre, bool boundsExpected = true) {
    ASSERT_EQ(mine.submeshes.size(), ogre.subs.size());
    EXPECT_TRUE(samePositions(mine.sharedPositions, ogre.sharedPositions)) << "shared vertices";
    for (size_t i = 0; i < ogre.subs.size(); ++i) {
        SCOPED_TRACE("submesh " + std::to_string(i));
        const MeshFile::SubMesh& s = mine.submeshes[i];
        const OgreMeshView::Sub& o = ogre.subs[i];
        EXPECT_EQ(s.material, o.material);
        EXPECT_EQ(s.sharedVertices, o.shared);
        EXPECT_EQ(static_cast<int>(s.operation), o.operation);
        EXPECT_TRUE(samePositions(s.positions, o.positions));
        EXPECT_TRUE(sameIndices(s.indices, expectedTriangles(o, ogre.positionsOf(o).size() / 3)));
    }
    if (boundsExpected) {
        ASSERT_TRUE(mine.bounds.has_value());
        EXPECT_EQ(mine.bounds->min.x, ogre.bounds.getMinimum().x);
        EXPECT_EQ(mine.bounds->min.y, ogre.bounds.getMinimum().y);
        EXPECT_EQ(mine.bounds->min.z, ogre.bounds.getMinimum().z);
        EXPECT_EQ(mine.bounds->max.x, ogre.bounds.getMaximum().x);
        EXPECT_EQ(mine.bounds->max.y, ogre.bounds.getMaximum().y);
        EXPECT_EQ(mine.bounds->max.z, ogre.bounds.getMaximum().z);
        EXPECT_EQ(mine.bounds->radius, ogre.radius);
    }
}

// What OGRE 1.12's writer gets wrong in the lengths it declares (the reader never relies on them,
// see engine_ext/mesh/README.md): M_ANIMATION leaves out its M_ANIMATION_BASEINFO child,
// M_ANIMATION_MORPH_KEYFRAME (v1.8 and later) its includesNormals flag, and M_MESH as a whole is
// short by those and by the edge lists of LOD levels beyond the first.
struct WriterQuirks {
    bool morphFlagUncounted = false;
    bool meshTotalUnreliable = false;
};

// Every chunk the reader walked ends exactly where its declared length says, once the writer's
// known miscounts are allowed for: the reader's idea of each chunk's layout is the writer's.
inline ::testing::AssertionResult chunksEndWhereDeclared(const std::vector<ChunkRecord>& chunks,
                                                         WriterQuirks quirks = {}) {
    std::ostringstream bad;
    int n = 0;
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        const ChunkRecord& c = chunks[i];
        const long long read = static_cast<long long>(c.end - c.offset);
        long long explained = 0;  // bytes the writer left out of this chunk's length
        for (std::size_t k = i + 1; k < chunks.size() && chunks[k].depth > c.depth; ++k) {
            const ChunkRecord& child = chunks[k];
            if (child.depth != c.depth + 1) continue;
            explained += static_cast<long long>(child.end - child.offset) - child.length;
            if (c.id == 0xD100 && child.id == 0xD105) explained += static_cast<long long>(child.end - child.offset);
        }
        if (c.id == 0xD111 && quirks.morphFlagUncounted) explained += 1;
        if (c.id == 0x3000 && quirks.meshTotalUnreliable) continue;
        if (read != static_cast<long long>(c.length) + explained && n++ < 8)
            bad << "\n  chunk 0x" << std::hex << c.id << std::dec << " at " << c.offset << " (depth " << c.depth
                << ") declares " << c.length << " bytes, the reader read " << read;
    }
    if (n) return ::testing::AssertionFailure() << n << " chunks:" << bad.str();
    return ::testing::AssertionSuccess();
}

}  // namespace obscura::mesh::testing
