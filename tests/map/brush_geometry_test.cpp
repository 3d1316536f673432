#include <gtest/gtest.h>

#include "map/brush_geometry.h"
#include "test_maps.h"

#include <cmath>

using namespace obscura;
using namespace obscura::map;

namespace {
MapBrush firstBrush(const std::string& brushText) {
    const MapFile m = parseMap(testdata::entity("\"classname\" \"worldspawn\"", brushText), "t.map");
    return m.entities.at(0).brushes.at(0);
}

double polygonArea(const BrushPolygon& p) {
    Vec3 s;
    for (std::size_t i = 1; i + 1 < p.points.size(); ++i)
        s += cross(p.points[i] - p.points[0], p.points[i + 1] - p.points[0]);
    return 0.5 * dot(s, p.normal);  // positive only if the winding is counter-clockwise from outside
}
}  // namespace

TEST(BrushGeometry, CubeGivesSixOutwardQuads) {
    const BrushResult r = buildBrush(firstBrush(testdata::cube(0, 0, 0)));
    ASSERT_TRUE(r.error.empty()) << r.error;
    ASSERT_EQ(r.polygons.size(), 6u);
    const Vec3 centre{32, 32, 32};
    for (const auto& p : r.polygons) {
        EXPECT_EQ(p.points.size(), 4u);
        EXPECT_NEAR(polygonArea(p), 64.0 * 64.0, 1e-6);  // CCW from outside, full face
        Vec3 c;
        for (const auto& q : p.points) c += q;
        c = c / 4.0;
        EXPECT_GT(dot(p.normal, c - centre), 0.0) << "normal points inwards";
        EXPECT_NEAR(std::fabs(dot(p.normal, c - centre)), 32.0, 1e-9);
    }
}

TEST(BrushGeometry, WedgeRampHasFiveFaces) {
    // A ramp: a 64-cube cut by a 45-degree plane through its bottom-front and top-back edges.
    std::string cube = testdata::cube(0, 0, 0);
    const std::string slope = "( 0 0 0 ) ( 0 1 0 ) ( 1 0 1 ) tex [ 1 0 0 0 ] [ 0 -1 0 0 ] 0 1 1\n";
    cube.insert(cube.size() - 2, slope);
    const BrushResult r = buildBrush(firstBrush(cube));
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.polygons.size(), 5u);  // the top face is clipped away entirely
    for (const auto& p : r.polygons) EXPECT_GT(polygonArea(p), 0.0);
}

TEST(BrushGeometry, RedundantPlaneIsDroppedNotFatal) {
    std::string cube = testdata::cube(0, 0, 0);
    // A plane outside the cube (x = 100, facing +x) clips nothing and yields no face.
    cube.insert(cube.size() - 2, "( 100 0 0 ) ( 100 0 1 ) ( 100 1 0 ) tex [ 1 0 0 0 ] [ 0 -1 0 0 ] 0 1 1\n");
    const BrushResult r = buildBrush(firstBrush(cube));
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.polygons.size(), 6u);
}

TEST(BrushGeometry, InvalidBrushesAreRejectedWithAMessage) {
    // Too few planes.
    EXPECT_NE(buildBrush(firstBrush("{\n( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) t 0 0 0 1 1\n}\n")).error.find("at least 4"), std::string::npos);
    // Collinear points.
    std::string bad = testdata::cube(0, 0, 0);
    bad.insert(bad.size() - 2, "( 0 0 0 ) ( 1 1 1 ) ( 2 2 2 ) t 0 0 0 1 1\n");
    EXPECT_NE(buildBrush(firstBrush(bad)).error.find("collinear"), std::string::npos);
    // Two opposite half-spaces that do not overlap: empty volume.
    std::string empty = testdata::cube(0, 0, 0);
    empty.insert(empty.size() - 2, "( 200 0 0 ) ( 200 1 0 ) ( 200 0 1 ) t [ 1 0 0 0 ] [ 0 -1 0 0 ] 0 1 1\n");  // x >= 200
    EXPECT_NE(buildBrush(firstBrush(empty)).error.find("no volume"), std::string::npos);
}

TEST(BrushGeometry, ValveTexelCoordinates) {
    MapFace f;
    f.valve220 = true;
    f.uAxis = {1, 0, 0};
    f.vAxis = {0, -1, 0};
    f.uOffset = 16;
    f.vOffset = -8;
    f.uScale = 2;
    f.vScale = 0.5;
    double u, v;
    faceTexel(f, {0, 0, 1}, {64, 10, 64}, u, v);
    EXPECT_DOUBLE_EQ(u, 64 / 2.0 + 16);
    EXPECT_DOUBLE_EQ(v, -10 / 0.5 - 8);
}

TEST(BrushGeometry, QuakeTexelCoordinatesWithRotation) {
    MapFace f;  // classic face on a floor: base axes x and -y
    f.uOffset = 4;
    f.vOffset = 8;
    f.uScale = 2;
    f.vScale = 1;
    double u, v;
    faceTexel(f, {0, 0, 1}, {64, 32, 64}, u, v);
    EXPECT_DOUBLE_EQ(u, 36);
    EXPECT_DOUBLE_EQ(v, -24);
    // Rotated 90 degrees, no shift/scale: the axes become +y and +x.
    MapFace r;
    r.rotation = 90;
    faceTexel(r, {0, 0, 1}, {10, 20, 0}, u, v);
    EXPECT_DOUBLE_EQ(u, 20);
    EXPECT_DOUBLE_EQ(v, 10);
    // A wall facing +x uses the y and -z axes.
    MapFace w;
    faceTexel(w, {1, 0, 0}, {0, 5, 7}, u, v);
    EXPECT_DOUBLE_EQ(u, 5);
    EXPECT_DOUBLE_EQ(v, -7);
}
