// Decals on bodies (engine_ext/decals/decal_attach.h): the box kept in the body's frame follows
// the body's translation and rotation exactly, a body that is gone drops its decals, a recycled
// slot forgets its body, fixed decals (signs) come first and are never recycled, and a body at
// rest costs no upload.
#include <gtest/gtest.h>

#include "decals/decal_attach.h"

#include <cmath>
#include <limits>

using namespace obscura;
using namespace obscura::decals;

namespace {
constexpr double kPi = 3.14159265358979323846;

BodyFrame turned(const Vec3& position, const Vec3& axis, double radians) {
    const Vec3 a = normalize(axis) * std::sin(radians / 2);
    return {position, a.x, a.y, a.z, std::cos(radians / 2)};
}

void expectNear(const Vec3& a, const Vec3& b, double tol = 1e-9) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// The box coordinates of a world point, through the rows the shader reads.
Vec3 toBox(const Decal& d, const Vec3& w) {
    const auto p = packDecal(d);
    auto row = [&](int i) { return p[i * 4] * w.x + p[i * 4 + 1] * w.y + p[i * 4 + 2] * w.z + p[i * 4 + 3]; };
    return {row(0), row(1), row(2)};
}

Decal hole(const Vec3& at, const Vec3& normal, double angle = 0.3) {
    Decal d;
    d.position = at;
    d.normal = normal;
    d.width = 0.08;
    d.height = 0.08;
    d.angle = angle;
    return d;
}
}  // namespace

TEST(DecalAttach, QuaternionRotationAndItsInverse) {
    const BodyFrame q = turned({1, 2, 3}, {0, 1, 0}, kPi / 2);  // 90 degrees about +y: x -> -z
    expectNear(rotate(q, {1, 0, 0}), {0, 0, -1});
    expectNear(rotateInverse(q, rotate(q, {0.3, -0.7, 2})), {0.3, -0.7, 2});
    expectNear(toLocal(q, toWorld(q, {0.2, 0.1, -0.4})), {0.2, 0.1, -0.4});
}

TEST(DecalAttach, WithFrameGivesTheSameBox) {
    // Walls, floors, ceilings and slanted faces; the tangent basis switches near |n.y| = 0.9.
    const Vec3 normals[] = {{1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0.3, 0.95, 0.1}, {-0.5, 0.2, 0.8}, {0, 0.89, 0.45}};
    for (const Vec3& n : normals)
        for (double angle : {0.0, 1.0, -2.5, 3.1}) {
            const Decal d = hole({0.5, 1, -2}, n, angle);
            const auto a = packDecal(d), b = packDecal(withFrame(d, boxFrame(d)));
            for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-5) << "normal " << n.x << " " << n.y << " " << n.z;
        }
}

TEST(DecalAttach, AHoleOnACrateFollowsItsFall) {
    // A 0.75 m crate at (0, 2, 0); a hole on its +x face. The crate falls off a ledge, tipping
    // 90 degrees about z: its +x face now faces up.
    DecalSet set(8);
    const BodyFrame onLedge{{0, 2, 0}};
    const Vec3 hit{0.375, 2.1, -0.05};
    ASSERT_TRUE(set.addOn(hole(hit, {1, 0, 0}), 0, onLedge));
    ASSERT_EQ(set.attachedCount(), 1);
    const BoxFrame before = boxFrame(set.list()[0]);

    const BodyFrame fallen = turned({1.2, 0.375, 0.3}, {0, 0, 1}, kPi / 2);
    set.follow({fallen});
    const Decal& d = set.list()[0];
    // The hit point is on the crate at (0.375, 0.1, -0.05) locally: rotated and moved with it.
    expectNear(d.position, toWorld(fallen, {0.375, 0.1, -0.05}));
    expectNear(d.position, {1.1, 0.75, 0.25});
    expectNear(normalize(d.normal), {0, 1, 0});
    // Its box turned with the crate about every axis (not only its normal): x and y follow too.
    const BoxFrame after = boxFrame(d);
    expectNear(after.x, rotate(fallen, before.x));
    expectNear(after.y, rotate(fallen, before.y));
    // The box maps the crate's surface point to its centre; a point 4 cm along the crate's face
    // (local -z) stays at the same box coordinates it had before the fall.
    const Vec3 alongFace{0.375, 2.1, -0.09};
    const Vec3 boxBefore = toBox(hole(hit, {1, 0, 0}), alongFace);
    expectNear(toBox(d, toWorld(fallen, {0.375, 0.1, -0.09})), boxBefore, 1e-5);
    expectNear(toBox(d, d.position), {0, 0, 0}, 1e-5);
}

TEST(DecalAttach, WorldDecalsStayAndRestingBodiesCostNoUpload) {
    DecalSet set(8);
    ASSERT_TRUE(set.add(hole({0, 1, 0}, {0, 0, 1})));
    ASSERT_TRUE(set.addOn(hole({2, 1, 0}, {0, 0, 1}), 0, BodyFrame{{2, 1, -0.2}}));
    set.follow({BodyFrame{{2, 1, -0.2}}});
    const auto v = set.version();
    set.follow({BodyFrame{{2, 1, -0.2}}});  // at rest: the same boxes
    EXPECT_EQ(set.version(), v);
    set.follow({BodyFrame{{3, 1, -0.2}}});  // moved 1 m east
    EXPECT_GT(set.version(), v);
    expectNear(set.list()[0].position, {0, 1, 0});
    expectNear(set.list()[1].position, {3, 1, 0});
}

TEST(DecalAttach, ABodyThatIsGoneDropsItsDecals) {
    DecalSet set(8);
    ASSERT_TRUE(set.addOn(hole({0, 1, 0.5}, {0, 0, 1}), 0, BodyFrame{{0, 1, 0}}));
    ASSERT_TRUE(set.addOn(hole({5, 1, 0.5}, {0, 0, 1}), 1, BodyFrame{{5, 1, 0}}));
    ASSERT_TRUE(set.add(hole({9, 1, 0}, {0, 0, 1})));
    set.follow({BodyFrame{{0, 1, 0}}});  // body 1 removed
    ASSERT_EQ(set.list().size(), 2u);
    expectNear(set.list()[1].position, {9, 1, 0});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    set.follow({BodyFrame{{nan, 1, 0}}, BodyFrame{{5, 1, 0}}});  // body 0 blew up; 1 is back
    ASSERT_EQ(set.list().size(), 1u) << "dropped decals stay dropped";
    EXPECT_EQ(set.attachedCount(), 0);
    EXPECT_FALSE(set.addOn(hole({0, 1, 0}, {0, 0, 1}), 0, BodyFrame{{nan, 0, 0}}));
    EXPECT_FALSE(set.addOn(hole({0, 1, 0}, {0, 0, 1}), -1, BodyFrame{}));
}

TEST(DecalAttach, ARecycledSlotForgetsItsBody) {
    DecalSet set(2);
    ASSERT_TRUE(set.addOn(hole({0, 1, 0.5}, {0, 0, 1}), 0, BodyFrame{{0, 1, 0}}));
    ASSERT_TRUE(set.add(hole({4, 1, 0}, {0, 0, 1})));
    ASSERT_TRUE(set.add(hole({6, 1, 0}, {0, 0, 1})));  // recycles slot 0
    EXPECT_EQ(set.attachedCount(), 0);
    set.follow({BodyFrame{{10, 1, 0}}});
    expectNear(set.list()[0].position, {6, 1, 0});
    set.follow({});  // no bodies at all: nothing attached, nothing dropped
    EXPECT_EQ(set.list().size(), 2u);
}

TEST(DecalAttach, FixedDecalsComeFirstAndAreNeverRecycled) {
    DecalSet set(1);
    Decal sign = hole({0, 2, -3}, {0, 0, 1});
    sign.width = 1.2;
    ASSERT_TRUE(set.addFixed(sign));
    Decal bad = sign;
    bad.width = 0;
    EXPECT_FALSE(set.addFixed(bad));
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(set.add(hole({double(i), 1, 0}, {0, 0, 1})));
    ASSERT_EQ(set.list().size(), 2u);
    EXPECT_EQ(set.list()[0].width, 1.2);
    expectNear(set.list()[1].position, {2, 1, 0});
    EXPECT_EQ(set.capacity(), 2);
}
