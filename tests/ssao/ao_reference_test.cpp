#include <gtest/gtest.h>

#include "ssao/ao_reference.h"
#include "floor_and_wall.h"

#include <cmath>

using namespace obscura;
using namespace obscura::ssao;

using obscura::testing_support::floorAndWall;

TEST(AoReference, OpenFloorIsUnoccluded) {
    const AoReference ref(floorAndWall());
    EXPECT_DOUBLE_EQ(ref.aoAt({0, 0, 5}, {0, 1, 0}, 1.0, 256, 1), 1.0);  // 5 m from the wall, radius 1 m
}

TEST(AoReference, FloorAtTheFootOfAWallIsHalfOccluded) {
    // Cosine-weighted: exactly half the directions lean towards the wall.
    const AoReference ref(floorAndWall());
    EXPECT_NEAR(ref.aoAt({0, 0, 0.01}, {0, 1, 0}, 100.0, 4096, 2), 0.5, 0.03);
}

TEST(AoReference, RadiusLimitsOcclusion) {
    // 1 m from the wall: with a 0.5 m radius nothing reaches it; with 100 m about a third is
    // blocked (the wall subtends less than half the hemisphere from there).
    const AoReference ref(floorAndWall());
    EXPECT_DOUBLE_EQ(ref.aoAt({0, 0, 1}, {0, 1, 0}, 0.5, 512, 3), 1.0);
    const double far = ref.aoAt({0, 0, 1}, {0, 1, 0}, 100.0, 4096, 3);
    EXPECT_GT(far, 0.55);
    EXPECT_LT(far, 0.9);
}

TEST(AoReference, ImageIsDeterministicAcrossThreadCounts) {
    const AoReference ref(floorAndWall());
    CameraPose pose;
    pose.eye = {0, 1.65, 4};
    pose.pitch = -0.3;
    const AoImage a = ref.render(pose, 48, 27, 0.6, 32, 1);
    const AoImage b = ref.render(pose, 48, 27, 0.6, 32, 3);
    EXPECT_EQ(a.ao, b.ao);
    // The crease between floor and wall is darker than the open floor below the camera.
    double crease = 1, open = 0;
    for (int x = 0; x < a.width; ++x) {
        for (int y = 0; y < a.height; ++y) crease = std::min(crease, static_cast<double>(a.ao[y * a.width + x]));
        open = std::max(open, static_cast<double>(a.ao[(a.height - 1) * a.width + x]));
    }
    EXPECT_LT(crease, 0.8);
    EXPECT_GT(open, 0.95);
}
