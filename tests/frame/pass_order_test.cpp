// render/pass_order_key.h: the draw order of a queue's passes follows their names only.
#include "render/pass_order_key.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

using obscura::render::passOrderKey;

TEST(PassOrderKey, SameNamesSameKeyInEveryRunAndEveryBuild) {
    // A fixed value: the key may not depend on anything but the names (no address, no seed).
    EXPECT_EQ(passOrderKey("baked/brick", "GBuffer", "GBuffer", 0), passOrderKey("baked/brick", "GBuffer", "GBuffer", 0));
    const std::uint32_t a = passOrderKey("baked/brick", "GBuffer", "GBuffer", 0);
    EXPECT_EQ(a >> 28, 0u);
    EXPECT_EQ(passOrderKey("baked/brick", "GBuffer", "GBuffer", 2) >> 28, 2u) << "the pass index in the top 4 bits";
    EXPECT_EQ(passOrderKey("baked/brick", "GBuffer", "GBuffer", 2) & 0x0fffffffu, a & 0x0fffffffu);
}

TEST(PassOrderKey, TheLevelMaterialsThatHashedAlikeDiffer) {
    // OGRE's default hash gave all four the same value on pool.map (pass_order_key.h).
    std::set<std::uint32_t> keys;
    for (const char* m : {"Obscura/Level/GBufferFallback", "baked/concrete", "baked/tile_floor", "baked/brick"})
        keys.insert(passOrderKey(m, "GBuffer", "GBuffer", 0));
    EXPECT_EQ(keys.size(), 4u);
    // Where the boundary between the names falls matters too.
    EXPECT_NE(passOrderKey("ab", "c", "", 0), passOrderKey("a", "bc", "", 0));
}

TEST(PassOrderKey, AThousandMaterialNamesKeepApart) {
    std::set<std::uint32_t> keys;
    for (int i = 0; i < 1000; ++i) keys.insert(passOrderKey("level/e3m4/tex" + std::to_string(i), "", "", 0));
    EXPECT_GE(keys.size(), 999u) << "28 bits: a collision among 1,000 names is about a 1-in-500 event";
}
