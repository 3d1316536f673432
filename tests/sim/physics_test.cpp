// The Bullet world on its own: colliders from a level, triangle meshes, crates, rays, sweeps, and
// bad input reported with its source position.
#include <gtest/gtest.h>

#include "sim/physics_world.h"
#include "sim_test_levels.h"

#include <string>

using namespace obscura;
using namespace obscura::sim;
using namespace obscura::sim::testlevels;

namespace {
constexpr double kGravity = 20;

// A 2 x 2 m horizontal quad at height y, centred on (cx, cz), as two triangles.
TriangleMesh quad(double cx, double cz, double y) {
    TriangleMesh m;
    m.vertices = {{cx - 1, y, cz - 1}, {cx + 1, y, cz - 1}, {cx + 1, y, cz + 1}, {cx - 1, y, cz + 1}};
    m.indices = {0, 2, 1, 0, 3, 2};
    return m;
}

std::string errorOf(const map::Level& l) {
    try {
        PhysicsWorld w(kGravity);
        w.addLevel(l);
    } catch (const SimError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(Physics, OneHullPerSolidBrushNonSolidSkipped) {
    map::Level l = floorLevel();
    map::LevelBrush water = box({-1, 0, -1}, {1, 1, 1});
    water.solid = false;
    l.brushes.push_back(water);
    l.brushes.push_back(box({4, 0, 4}, {5, 1, 5}));
    PhysicsWorld w(kGravity);
    w.addLevel(l);
    EXPECT_EQ(w.staticBodyCount(), 2u);
    EXPECT_EQ(w.dynamicBodyCount(), 0u);
    // A ray down through the water reaches the floor; one through the solid box stops on its top.
    const auto throughWater = w.rayCast({0, 5, 0}, {0, -5, 0});
    ASSERT_TRUE(throughWater);
    EXPECT_NEAR(throughWater->point.y, 0.0, 2e-3);  // within the 1 mm hull margin
    const auto onBox = w.rayCast({4.5, 5, 4.5}, {4.5, -5, 4.5});
    ASSERT_TRUE(onBox);
    EXPECT_NEAR(onBox->point.y, 1.0, 2e-3);
}

TEST(Physics, RayCastReportsPointNormalAndWhatWasHit) {
    map::Level l = floorLevel();
    l.brushes.push_back(box({-20, 0, -6}, {20, 3, -5}));  // wall face at z = -5
    l.entities.push_back(crate({3, 0, 0}));
    PhysicsWorld w(kGravity);
    w.addLevel(l);
    ASSERT_EQ(w.dynamicBodyCount(), 1u);

    const auto wall = w.rayCast({0, 1, 0}, {0, 1, -10});
    ASSERT_TRUE(wall);
    EXPECT_NEAR(wall->point.z, -5.0, 2e-3);
    EXPECT_NEAR(wall->normal.z, 1.0, 1e-4);  // facing the ray
    EXPECT_NEAR(wall->fraction, 0.5, 1e-3);
    EXPECT_EQ(wall->dynamicBody, -1);

    const auto box = w.rayCast({0, 0.3, 0}, {10, 0.3, 0});  // towards the crate (x 2.625..3.375)
    ASSERT_TRUE(box);
    EXPECT_EQ(box->dynamicBody, 0);
    EXPECT_NEAR(box->point.x, 3 - 0.375, 0.01);
    EXPECT_NEAR(box->normal.x, -1.0, 1e-3);

    EXPECT_FALSE(w.rayCast({0, 5, 0}, {0, 50, 0}));  // into the open sky
    EXPECT_FALSE(w.rayCast({0, 5, 0}, {0, 5, 0}));   // a zero-length ray hits nothing
}

TEST(Physics, TriangleMeshCollidesAndOnlyWhereItIs) {
    PhysicsWorld w(kGravity);
    w.addStaticTriangleMesh(quad(0, 0, 2));
    EXPECT_EQ(w.staticBodyCount(), 1u);
    const auto hit = w.rayCast({0.5, 5, 0.5}, {0.5, -5, 0.5});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->point.y, 2.0, 1e-4);
    EXPECT_NEAR(hit->normal.y, 1.0, 1e-4);
    EXPECT_FALSE(w.rayCast({3, 5, 0}, {3, -5, 0}));  // beside the quad
    // A capsule swept down onto it stops with its bottom on the quad.
    btCapsuleShape capsule(0.35f, 1.1f);
    const auto sweep = w.sweep(capsule, {0, 10, 0}, {0, 0, 0});  // centre 0.9 m above the bottom
    ASSERT_TRUE(sweep);
    EXPECT_NEAR(10 - 10 * sweep->fraction, 2.0 + 0.9, 0.01);
    EXPECT_NEAR(sweep->normal.y, 1.0, 1e-3);
}

TEST(Physics, PlayerLandsOnAModelMesh) {
    map::Level l;  // no brushes at all: the model is the only floor
    l.entities.push_back({});
    l.hasPlayerStart = true;
    l.playerStart = {0, 5, 0};
    Simulation s(l, {}, {quad(0, 0, 1)});
    run(s, {}, 90);
    EXPECT_TRUE(s.player().onGround);
    EXPECT_NEAR(s.player().feet.y, 1.0, 0.01);
}

TEST(Physics, SweepIgnoresWhatItMovesAwayFromOrAlong) {
    PhysicsWorld w(kGravity);
    w.addLevel(floorLevel());
    btCapsuleShape capsule(0.35f, 1.1f);
    const Vec3 resting{0, 0.9, 0};  // bottom exactly on the floor (inside its 1 mm margin)
    EXPECT_FALSE(w.sweep(capsule, resting, resting + Vec3{0, 1, 0}));  // lifting off
    EXPECT_FALSE(w.sweep(capsule, resting, resting + Vec3{3, 0, 0}));  // sliding along
    const auto down = w.sweep(capsule, resting, resting - Vec3{0, 1, 0});
    ASSERT_TRUE(down);  // pressing into it
    EXPECT_LT(down->fraction, 0.01);
}

TEST(Physics, CratesFallAndComeToRest) {
    map::Level l = floorLevel();
    for (int i = 0; i < 3; ++i) l.entities.push_back(crate({-1.0 + 1.2 * i, 1.0 + i, -3}));  // dropped
    map::LevelEntity big = crate({3, 0, 3});
    big.keys = {{"size", "1.5"}, {"mass", "80"}};
    l.entities.push_back(big);
    Simulation s(l, {});
    run(s, {}, 300);
    const auto poses = s.bodyPoses();
    ASSERT_EQ(poses.size(), 4u);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(poses[i].position.y, 0.375, 0.01) << "crate " << i;  // on the floor, not in it
        EXPECT_NEAR(poses[i].position.x, -1.0 + 1.2 * i, 0.05) << "crate " << i;
        EXPECT_NEAR(poses[i].halfExtents.x, 0.375, 1e-9);
        EXPECT_NEAR(std::abs(poses[i].qw), 1.0, 1e-3) << "crate " << i;  // landed flat, upright
        EXPECT_LT(s.physics().dynamicBody(static_cast<std::size_t>(i)).getLinearVelocity().length(), 0.01);
    }
    EXPECT_NEAR(poses[3].position.y, 0.75, 0.01);
    EXPECT_NEAR(poses[3].halfExtents.y, 0.75, 1e-9);
    EXPECT_NEAR(1.0 / s.physics().dynamicBody(3).getInvMass(), 80.0, 1e-3);
}

TEST(Physics, StackedCratesStayStacked) {
    map::Level l = floorLevel();
    l.entities.push_back(crate({0, 0, -3}));
    l.entities.push_back(crate({0, 0.75, -3}));
    Simulation s(l, {});
    run(s, {}, 240);
    const auto poses = s.bodyPoses();
    EXPECT_NEAR(poses[1].position.y, 0.75 + 0.375, 0.01);
    EXPECT_NEAR(poses[1].position.x, 0.0, 0.01);
}

TEST(Physics, BadInputNamesFileLineAndColumn) {
    map::Level l = floorLevel();
    map::LevelEntity e = crate({0, 0, 0});
    e.pos = {12, 3};
    e.keys = {{"size", "big"}};
    l.entities.push_back(e);
    std::string err = errorOf(l);
    EXPECT_NE(err.find("test.map:12:3: prop_crate key 'size' is 'big'"), std::string::npos) << err;

    l.entities.back().keys = {{"mass", "-5"}};
    err = errorOf(l);
    EXPECT_NE(err.find("test.map:12:3: prop_crate key 'mass' is '-5'"), std::string::npos) << err;

    l.entities.back().keys = {};
    l.entities.back().hasOrigin = false;
    err = errorOf(l);
    EXPECT_NE(err.find("test.map:12:3: prop_crate without an 'origin'"), std::string::npos) << err;

    map::Level flat = floorLevel();
    map::LevelBrush sheet = box({0, 1, 0}, {1, 1, 1});  // zero thickness
    sheet.pos = {40, 1};
    flat.brushes.push_back(sheet);
    err = errorOf(flat);
    EXPECT_NE(err.find("test.map:40:1: solid brush is degenerate"), std::string::npos) << err;

    PhysicsWorld w(kGravity);
    TriangleMesh bad = quad(0, 0, 0);
    bad.indices[4] = 7;
    EXPECT_THROW(w.addStaticTriangleMesh(bad), SimError);
    bad.indices.pop_back();
    EXPECT_THROW(w.addStaticTriangleMesh(bad), SimError);
    EXPECT_EQ(w.staticBodyCount(), 0u);
}

TEST(Physics, WorldsComeAndGoCleanly) {
    // Build and destroy a world with every kind of body, repeatedly; under a leak checker or
    // ASan this catches a wrong destruction order. Here: it must not crash, and each world is fresh.
    for (int i = 0; i < 20; ++i) {
        map::Level l = floorLevel();
        l.entities.push_back(crate({0, 1, 0}));
        PhysicsWorld w(kGravity);
        w.addLevel(l);
        w.addStaticTriangleMesh(quad(5, 5, 1));
        for (int t = 0; t < 10; ++t) w.step(1.0 / 60);
        EXPECT_EQ(w.staticBodyCount(), 2u);
        EXPECT_EQ(w.dynamicBodyCount(), 1u);
    }
}
