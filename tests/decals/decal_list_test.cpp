// The decal ring buffer and each decal's box: the cap recycles the oldest, bad decals are refused
// with a reason, the packed rows map the box to [-1, 1]^3 with z along the normal, placement is a
// function of the serial number alone.
#include <gtest/gtest.h>

#include "decals/decal_list.h"

#include <cmath>
#include <limits>

using namespace obscura;
using namespace obscura::decals;

namespace {
Vec3 toBox(const std::array<float, DECAL_TEXELS * 4>& p, const Vec3& w) {
    auto row = [&](int i) { return p[i * 4] * w.x + p[i * 4 + 1] * w.y + p[i * 4 + 2] * w.z + p[i * 4 + 3]; };
    return {row(0), row(1), row(2)};
}
}  // namespace

TEST(DecalRing, CapRecyclesTheOldest) {
    DecalRing ring(3);
    for (int i = 0; i < 5; ++i) {
        Decal d;
        d.position = {double(i), 0, 0};
        ASSERT_TRUE(ring.add(d));
    }
    ASSERT_EQ(ring.size(), 3);
    // Slots 0 and 1 were recycled by decals 3 and 4; slot 2 keeps decal 2.
    EXPECT_EQ(ring.slots()[0].position.x, 3);
    EXPECT_EQ(ring.slots()[1].position.x, 4);
    EXPECT_EQ(ring.slots()[2].position.x, 2);
    EXPECT_EQ(ring.added(), 5u);
    EXPECT_EQ(DecalRing(0).capacity(), 1);
    EXPECT_EQ(DecalRing(100000).capacity(), DECAL_MAX_CAP);
}

TEST(DecalRing, BadDecalsAreRefusedWithAReason) {
    DecalRing ring(4);
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    Decal d;
    d.position = {nan, 0, 0};
    EXPECT_EQ(validate(d), "non-finite position");
    d = Decal{};
    d.normal = {0, 0, 0};
    EXPECT_EQ(validate(d), "no usable normal");
    d = Decal{};
    d.width = 0;
    EXPECT_EQ(validate(d), "zero or non-finite size");
    d = Decal{};
    d.depth = inf;
    EXPECT_EQ(validate(d), "zero or non-finite size");
    d = Decal{};
    d.angle = inf;
    EXPECT_EQ(validate(d), "non-finite angle");
    d = Decal{};
    d.tile = DECAL_MAX_TILES;
    EXPECT_NE(validate(d).find("tile"), std::string::npos);
    EXPECT_FALSE(ring.add(d));
    EXPECT_EQ(ring.size(), 0);
    EXPECT_EQ(ring.version(), 0u);
}

TEST(DecalBox, RowsMapTheBoxToTheUnitCube) {
    for (const Vec3 n : {Vec3{0, 1, 0}, Vec3{1, 0, 0}, Vec3{0, 0, -1}, Vec3{0.3, 0.4, -0.866}}) {
        Decal d;
        d.position = {2, 1, -3};
        d.normal = n;
        d.width = 0.4, d.height = 0.2, d.depth = 0.1, d.angle = 0.7;
        const auto p = packDecal(d);
        const Vec3 c = toBox(p, d.position);
        EXPECT_NEAR(length(c), 0, 1e-5);
        const Vec3 nz = normalize(n);
        const Vec3 front = toBox(p, d.position + nz * 0.05);  // half the depth along the normal: z = +1
        EXPECT_NEAR(front.z, 1, 1e-5);
        EXPECT_NEAR(front.x, 0, 1e-5);
        EXPECT_NEAR(front.y, 0, 1e-5);
        // The x and y rows are orthogonal to the normal with the half sizes' lengths.
        EXPECT_NEAR(std::hypot(p[0], p[1], p[2]), 1 / 0.2, 1e-4);
        EXPECT_NEAR(std::hypot(p[4], p[5], p[6]), 1 / 0.1, 1e-4);
        EXPECT_NEAR(p[0] * nz.x + p[1] * nz.y + p[2] * nz.z, 0, 1e-4);
        EXPECT_NEAR(p[4] * nz.x + p[5] * nz.y + p[6] * nz.z, 0, 1e-4);
    }
}

TEST(DecalBox, PlacementDependsOnTheSerialNumberAlone) {
    const Decal a = bulletHole({1, 2, 3}, {0, 0, 1}, 7), b = bulletHole({1, 2, 3}, {0, 0, 1}, 7), c = bulletHole({1, 2, 3}, {0, 0, 1}, 8);
    EXPECT_EQ(a.angle, b.angle);
    EXPECT_EQ(a.width, b.width);
    EXPECT_NE(a.angle, c.angle);
    EXPECT_GE(a.width, 0.07);
    EXPECT_LE(a.width, 0.10);
    EXPECT_TRUE(validate(scorch({0, 0, 0}, 3)).empty());
}
