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

Vec3 centroid(const std::vector<Vec3>& pts) {
    Vec3 c;
    for (const auto& q : pts) c += q;
    return c / static_cast<double>(pts.size());
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

// The cube TrenchBroom creates in a Quake-format map (its new-brush default, 128 x 128 x 32),
// written exactly as TrenchBroom saves it: the three points of each face run so that
// cross(p3 - p1, p2 - p1) points out of the brush.
static const char* kTrenchBroomCube =
    "{\n"
    "( -64 -64 -16 ) ( -64 -63 -16 ) ( -64 -64 -15 ) side 0 0 0 1 1\n"
    "( -64 -64 -16 ) ( -64 -64 -15 ) ( -63 -64 -16 ) side 0 0 0 1 1\n"
    "( -64 -64 -16 ) ( -63 -64 -16 ) ( -64 -63 -16 ) floor 0 0 0 1 1\n"
    "( 64 64 16 ) ( 64 65 16 ) ( 65 64 16 ) top 8 16 0 2 0.5\n"
    "( 64 64 16 ) ( 65 64 16 ) ( 64 64 17 ) side 0 0 0 1 1\n"
    "( 64 64 16 ) ( 64 64 17 ) ( 64 65 16 ) side 0 0 0 1 1\n"
    "}\n";

TEST(BrushGeometry, TrenchBroomCubeHasOutwardNormals) {
    const BrushResult r = buildBrush(firstBrush(kTrenchBroomCube));
    ASSERT_TRUE(r.error.empty()) << r.error;
    ASSERT_EQ(r.polygons.size(), 6u);
    // Face order is file order: -x, -y, -z, +z, +y, +x.
    const Vec3 expected[6] = {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
    const double areas[6] = {128 * 32, 128 * 32, 128 * 128, 128 * 128, 128 * 32, 128 * 32};
    for (std::size_t i = 0; i < 6; ++i) {
        const BrushPolygon& p = r.polygons[i];
        EXPECT_EQ(p.faceIndex, static_cast<int>(i));
        EXPECT_NEAR(length(p.normal - expected[i]), 0.0, 1e-12) << "face " << i;
        EXPECT_NEAR(polygonArea(p), areas[i], 1e-6) << "face " << i;
    }
}

TEST(BrushGeometry, QuakeFaceTexelsThroughTheBrush) {
    const BrushResult r = buildBrush(firstBrush(kTrenchBroomCube));
    ASSERT_EQ(r.polygons.size(), 6u);
    // The top face (+z, "top 8 16 0 2 0.5") projects on Quake's floor axes x and -y:
    // u = x / 2 + 8, v = -y / 0.5 + 16, worked out per corner.
    const BrushPolygon& top = r.polygons[3];
    ASSERT_EQ(top.points.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k) {
        const Vec3& q = top.points[k];
        const double x = q.x, y = q.y;  // each corner is (+-64, +-64, 16)
        EXPECT_DOUBLE_EQ(top.u[k], x > 0 ? 40 : -24);
        EXPECT_DOUBLE_EQ(top.v[k], y > 0 ? -112 : 144);
    }
    // The -x wall ("side 0 0 0 1 1") uses the east-wall axes +y and -z: u = y, v = -z.
    const BrushPolygon& west = r.polygons[0];
    for (std::size_t k = 0; k < west.points.size(); ++k) {
        EXPECT_DOUBLE_EQ(west.u[k], west.points[k].y);
        EXPECT_DOUBLE_EQ(west.v[k], -west.points[k].z);
    }
}

TEST(BrushGeometry, TetrahedronIsTheSmallestBrush) {
    // Four planes through the corners O=(0,0,0), X=(64,0,0), Y=(0,64,0), Z=(0,0,64); each face's
    // points ordered so that cross(p3 - p1, p2 - p1) points away from the fourth corner.
    const BrushResult r = buildBrush(firstBrush(
        "{\n"
        "( 0 0 0 ) ( 64 0 0 ) ( 0 64 0 ) t 0 0 0 1 1\n"   // z = 0, normal -z
        "( 0 0 0 ) ( 0 0 64 ) ( 64 0 0 ) t 0 0 0 1 1\n"   // y = 0, normal -y
        "( 0 0 0 ) ( 0 64 0 ) ( 0 0 64 ) t 0 0 0 1 1\n"   // x = 0, normal -x
        "( 64 0 0 ) ( 0 0 64 ) ( 0 64 0 ) t 0 0 0 1 1\n"  // x + y + z = 64, normal +(1,1,1)
        "}\n"));
    ASSERT_TRUE(r.error.empty()) << r.error;
    ASSERT_EQ(r.polygons.size(), 4u);
    for (const auto& p : r.polygons) {
        EXPECT_EQ(p.points.size(), 3u);
        EXPECT_GT(dot(p.normal, centroid(p.points) - Vec3{16, 16, 16}), 0.0);
    }
    EXPECT_NEAR(polygonArea(r.polygons[0]), 64.0 * 64.0 / 2, 1e-6);
    EXPECT_NEAR(polygonArea(r.polygons[3]), std::sqrt(3.0) / 4 * (64 * std::sqrt(2.0)) * (64 * std::sqrt(2.0)), 1e-6);
}

TEST(BrushGeometry, DuplicatePlaneKeepsOneFace) {
    std::string cube = testdata::cube(0, 0, 0);
    // The bottom plane again, its points in another order and place: the same plane.
    cube.insert(cube.size() - 2, "( 10 10 0 ) ( 11 10 0 ) ( 10 11 0 ) dup [ 1 0 0 0 ] [ 0 -1 0 0 ] 0 1 1\n");
    const BrushResult r = buildBrush(firstBrush(cube));
    ASSERT_TRUE(r.error.empty()) << r.error;
    ASSERT_EQ(r.polygons.size(), 6u);
    for (const auto& p : r.polygons) EXPECT_NE(p.faceIndex, 6) << "the later duplicate must not make a second face";
}

TEST(BrushGeometry, OppositeCoplanarPlanesLeaveNoVolume) {
    std::string slab = testdata::cube(0, 0, 0);
    // z <= 0 (normal +z through the bottom face): together with z >= 0 the brush is flat.
    slab.insert(slab.size() - 2, "( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) t [ 1 0 0 0 ] [ 0 -1 0 0 ] 0 1 1\n");
    const BrushResult r = buildBrush(firstBrush(slab));
    EXPECT_TRUE(r.polygons.empty());
    EXPECT_NE(r.error.find("no volume"), std::string::npos) << r.error;
}

TEST(BrushGeometry, OpenPrismIsNotClosed) {
    // The four side walls of the 64 cube without floor or ceiling: infinite along z.
    const BrushResult r = buildBrush(firstBrush(
        "{\n"
        "( 0 0 0 ) ( 0 1 0 ) ( 0 0 1 ) t 0 0 0 1 1\n"
        "( 0 0 0 ) ( 0 0 1 ) ( 1 0 0 ) t 0 0 0 1 1\n"
        "( 64 64 64 ) ( 65 64 64 ) ( 64 64 65 ) t 0 0 0 1 1\n"
        "( 64 64 64 ) ( 64 64 65 ) ( 64 65 64 ) t 0 0 0 1 1\n"
        "}\n"));
    EXPECT_TRUE(r.polygons.empty());
    EXPECT_NE(r.error.find("not closed"), std::string::npos) << r.error;
}

TEST(BrushGeometry, InvertedBrushIsEmpty) {
    // The TrenchBroom cube with every face's winding reversed (p2 and p3 swapped): each plane now
    // faces inwards, the half-spaces do not overlap, and the brush must be rejected, not turned
    // inside out.
    std::string text = kTrenchBroomCube;
    std::string flipped;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        std::string line = text.substr(start, end - start);
        if (!line.empty() && line[0] == '(') {
            const std::size_t a = line.find(") (") + 2, b = line.find(") (", a) + 2, c = line.find(')', b) + 1;
            line = line.substr(0, a) + line.substr(b, c - b) + " " + line.substr(a, b - a - 1) + line.substr(c);
        }
        flipped += line + "\n";
        start = end + 1;
    }
    ASSERT_NE(flipped, text);
    const BrushResult r = buildBrush(firstBrush(flipped));
    EXPECT_TRUE(r.polygons.empty());
    EXPECT_FALSE(r.error.empty());
}
