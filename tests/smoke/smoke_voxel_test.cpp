// Obstacles: conservative voxelisation (thin walls at any angle, meshes, a real map) and the
// solver keeping smoke where it can physically be.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>

#include "core/rng.h"
#include "map/map_compile.h"
#include "smoke/voxelize.h"
#include "smoke_test_levels.h"

using namespace obscura;
using namespace obscura::smoke;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Does the segment a-b pass through the hull's interior (deeper than `eps`)?
bool segmentCrossesHull(const Vec3& a, const Vec3& b, const ConvexHull& hull, double eps = 1e-6) {
    double t0 = 0, t1 = 1;
    for (const Plane& p : hull.planes) {
        const double da = dot(p.normal, a) - p.offset + eps, db = dot(p.normal, b) - p.offset + eps;
        if (da > 0 && db > 0) return false;
        if (da > 0) t0 = std::max(t0, da / (da - db));
        else if (db > 0) t1 = std::min(t1, da / (da - db));
        if (t0 > t1) return false;
    }
    return true;
}

// The no-leak property the solver relies on: no two free cells that touch (even at a corner)
// have the segment between their centres crossing a solid hull. Returns the number of offenders.
int countLeakyPairs(const SmokeVolume& vol, const std::vector<ConvexHull>& hulls) {
    const GridInfo& g = vol.grid();
    int bad = 0;
    for (const ConvexHull& hull : hulls) {
        const Vec3 lo = g.toCellCoords(hull.bounds.min), hi = g.toCellCoords(hull.bounds.max);
        const int i0 = std::max(0, static_cast<int>(std::floor(lo.x)) - 1), i1 = std::min(g.nx - 1, static_cast<int>(std::ceil(hi.x)) + 1);
        const int j0 = std::max(0, static_cast<int>(std::floor(lo.y)) - 1), j1 = std::min(g.ny - 1, static_cast<int>(std::ceil(hi.y)) + 1);
        const int k0 = std::max(0, static_cast<int>(std::floor(lo.z)) - 1), k1 = std::min(g.nz - 1, static_cast<int>(std::ceil(hi.z)) + 1);
        for (int k = k0; k <= k1; ++k)
            for (int j = j0; j <= j1; ++j)
                for (int i = i0; i <= i1; ++i) {
                    if (vol.voxelSolidAt(i, j, k)) continue;
                    for (int dk = 0; dk <= 1; ++dk)
                        for (int dj = -1; dj <= 1; ++dj)
                            for (int di = -1; di <= 1; ++di) {
                                if (dk == 0 && (dj < 0 || (dj == 0 && di <= 0))) continue;  // each pair once
                                const int a = i + di, b = j + dj, c = k + dk;
                                if (!g.contains(a, b, c) || vol.voxelSolidAt(a, b, c)) continue;
                                if (segmentCrossesHull(g.cellCentre(i, j, k), g.cellCentre(a, b, c), hull)) ++bad;
                            }
                }
    }
    return bad;
}

// Random points strictly inside a hull (convex combinations of its vertices) land in solid cells.
int countFreeCellsInside(const SmokeVolume& vol, const ConvexHull& hull, Rng& rng, int samples) {
    const GridInfo& g = vol.grid();
    int bad = 0;
    for (int s = 0; s < samples; ++s) {
        Vec3 p;
        double total = 0;
        for (const Vec3& q : hull.points) {
            const double w = 0.05 + rng.nextU32() / 4294967296.0;
            p += q * w;
            total += w;
        }
        p = p / total;
        const Vec3 c = g.toCellCoords(p);
        const int i = static_cast<int>(std::lround(c.x)), j = static_cast<int>(std::lround(c.y)), k = static_cast<int>(std::lround(c.z));
        if (g.contains(i, j, k) && !vol.voxelSolidAt(i, j, k)) ++bad;
    }
    return bad;
}

std::vector<ConvexHull> hullsOf(const map::Level& l, const std::function<bool(const map::LevelBrush&)>& keep) {
    std::vector<ConvexHull> out;
    for (const auto& b : l.brushes)
        if (b.solid && keep(b)) out.push_back(makeHull(b));
    return out;
}

// Density anywhere on the far side (signed distance > margin) of a plane through `p` with normal n.
double densityBeyond(const SmokeVolume& vol, const Vec3& p, const Vec3& n, double margin) {
    const GridInfo& g = vol.grid();
    double sum = 0;
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                if (dot(g.cellCentre(i, j, k) - p, n) > margin) sum += vol.densityAt(i, j, k);
    return sum;
}

bool densityOnlyInFluid(const SmokeVolume& vol) {
    const GridInfo& g = vol.grid();
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                if (vol.solidAt(i, j, k) && vol.densityAt(i, j, k) != 0.f) return false;
    return true;
}

// A room 5 x 2.75 x 5 split by a wall of `thickness` through (wx, *, *) rotated by `yaw`, long
// enough to cut into the outer walls. Smoke starts on the -x side.
map::Level splitRoom(double wx, double thickness, double yaw) {
    map::Level l;
    testlevels::addRoom(l, {-2.5, 0, -2.5}, {2.5, 2.75, 2.5}, 0.25);
    l.brushes.push_back(testlevels::rotatedBox({wx, 1.375, 0}, {thickness / 2, 1.5, 4.0}, yaw));
    testlevels::finish(l);
    return l;
}

void runSplitRoom(double thickness, double yaw) {
    const double wx = 0.43;  // not on a cell boundary
    const map::Level level = splitRoom(wx, thickness, yaw);
    SmokeSettings st = testlevels::small(24);  // the full 60 m^3 of gas pushes hard against the wall
    SmokeVolume vol = SmokeVolume::create(level, {}, {-1.2, 0.1, 0}, st);
    EXPECT_EQ(countLeakyPairs(vol, hullsOf(level, [](const map::LevelBrush&) { return true; })), 0);
    const Vec3 n{std::cos(yaw), 0, -std::sin(yaw)};  // the wall's normal (rotatedBox's local +x)
    for (int i = 0; i < 90; ++i) {
        vol.step(1.0 / 30);
        ASSERT_TRUE(densityOnlyInFluid(vol)) << "step " << i;
    }
    EXPECT_GT(densityBeyond(vol, {wx, 0, 0}, -n, thickness), 1.0) << "smoke reached the wall's own side";
    EXPECT_EQ(densityBeyond(vol, {wx, 0, 0}, n, thickness / 2 + 0.01), 0.0) << "leak through the wall";
}

}  // namespace

TEST(SmokeVoxel, BoxOverlapBasics) {
    ConvexHull hull = makeHull(testlevels::box({0, 0, 0}, {1, 1, 1}));
    EXPECT_TRUE(boxOverlapsHull({0.5, 0.5, 0.5}, {2, 2, 2}, hull, 1e-9));
    EXPECT_FALSE(boxOverlapsHull({1, 0, 0}, {2, 1, 1}, hull, 1e-9)) << "touching is not overlapping";
    EXPECT_FALSE(boxOverlapsHull({1.01, 0, 0}, {2, 1, 1}, hull, 1e-9));
    // A 45-degree slab along x = z: a box off the diagonal overlaps its AABB but not the slab.
    ConvexHull diag = makeHull(testlevels::rotatedBox({0, 0, 0}, {0.05, 1, 2}, kPi / 4));
    EXPECT_TRUE(boxOverlapsHull({-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}, diag, 1e-9));
    EXPECT_FALSE(boxOverlapsHull({0.6, -0.1, -0.8}, {0.8, 0.1, -0.6}, diag, 1e-9));
    EXPECT_TRUE(boxOverlapsHull({0.5, -0.1, 0.6}, {0.7, 0.1, 0.8}, diag, 1e-9));
    // Planes from hull points alone (no faces) give the same answers.
    map::LevelBrush pointsOnly = testlevels::rotatedBox({0, 0, 0}, {0.05, 1, 2}, kPi / 4);
    pointsOnly.faces.clear();
    ConvexHull fromPoints = makeHull(pointsOnly);
    EXPECT_GE(fromPoints.planes.size(), 6u);
    EXPECT_TRUE(boxOverlapsHull({-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}, fromPoints, 1e-9));
    EXPECT_FALSE(boxOverlapsHull({0.6, -0.1, -0.8}, {0.8, 0.1, -0.6}, fromPoints, 1e-9));
    // Triangles.
    EXPECT_TRUE(boxOverlapsTriangle({0, 0, 0}, {1, 1, 1}, {-1, 0.5, -1}, {3, 0.5, -1}, {-1, 0.5, 3}, 1e-9));
    EXPECT_FALSE(boxOverlapsTriangle({0, 0, 0}, {1, 1, 1}, {-1, 1.5, -1}, {3, 1.5, -1}, {-1, 1.5, 3}, 1e-9));
    EXPECT_FALSE(boxOverlapsTriangle({0, 0, 0}, {1, 1, 1}, {1.2, 0, 0}, {3, 0, 0}, {1.2, 3, 3}, 1e-9));
}

TEST(SmokeVoxel, ThinAxisAlignedWallDoesNotLeak) { runSplitRoom(0.05, 0.0); }
TEST(SmokeVoxel, OneCellWallDoesNotLeak) { runSplitRoom(0.25, 0.0); }
TEST(SmokeVoxel, ThinDiagonalWallDoesNotLeak) { runSplitRoom(0.05, kPi / 4); }
TEST(SmokeVoxel, ThinSkewedWallDoesNotLeak) { runSplitRoom(0.04, 0.3); }

TEST(SmokeVoxel, ClosedRoomKeepsItsSmoke) {
    map::Level level;
    testlevels::addRoom(level, {-1.5, 0, -1.5}, {1.5, 2.5, 1.5}, 0.1);
    level.brushes.push_back(testlevels::box({-8, -1, -8}, {8, -0.2, 8}));  // a big floor: open space around
    level.brushes.push_back(testlevels::box({-8, 5, -8}, {8, 6, 8}));      // and a sky lid far up
    testlevels::finish(level);
    SmokeSettings st = testlevels::small(32);
    SmokeVolume vol = SmokeVolume::create(level, {}, {0, 0.1, 0}, st);
    for (int i = 0; i < 90; ++i) vol.step(1.0 / 30);
    const GridInfo& g = vol.grid();
    double inside = 0, outside = 0;
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const Vec3 p = g.cellCentre(i, j, k);
                const bool in = std::fabs(p.x) < 1.5 && std::fabs(p.z) < 1.5 && p.y > 0 && p.y < 2.5;
                (in ? inside : outside) += vol.densityAt(i, j, k);
            }
    EXPECT_GT(inside, 10.0);
    EXPECT_EQ(outside, 0.0);
}

TEST(SmokeVoxel, SmokeFlowsThroughADoorway) {
    const map::Level level = testlevels::doorwayRooms();
    SmokeSettings st = testlevels::small(32);
    SmokeVolume vol = SmokeVolume::create(level, {}, {-1.5, 0.1, 0}, st);
    for (int i = 0; i < 120; ++i) vol.step(1.0 / 30);
    const double beyond = densityBeyond(vol, {0.2, 0, 0}, {1, 0, 0}, 0.0);
    std::cout << "density through the door: " << beyond << " of " << vol.totalDensity() / std::pow(0.25, 3) << "\n";
    EXPECT_GT(beyond, 1.0);
}

TEST(SmokeVoxel, TriangleMeshWallDoesNotLeak) {
    // A thin diagonal wall made of two triangles (a prop's surface), cutting the room.
    const map::Level level = testlevels::closedRoom({-2.5, 0, -2.5}, {2.5, 2.75, 2.5});
    TriangleMesh wall;
    wall.vertices = {{-2.6, -0.1, -1.9}, {2.9, -0.1, 3.6}, {2.9, 3.0, 3.6}, {-2.6, 3.0, -1.9}};  // x - z = -0.7
    wall.indices = {0, 1, 2, 0, 2, 3};
    SmokeSettings st = testlevels::small(24);
    SmokeVolume vol = SmokeVolume::create(level, {wall}, {0.5, 0.1, -1.0}, st);  // x - z = 1.5 side
    for (int i = 0; i < 90; ++i) vol.step(1.0 / 30);
    const Vec3 n = normalize(Vec3{-1, 0, 1});  // toward x - z < -0.7
    const Vec3 onWall{0, 0, 0.7};
    EXPECT_GT(densityBeyond(vol, onWall, -n, 0.2), 1.0);
    EXPECT_EQ(densityBeyond(vol, onWall, n, 0.01), 0.0);
}

TEST(SmokeVoxel, LibreQuakeE3m4NonAxisAlignedBrushes) {
    const auto path = std::filesystem::path(OBSCURA_THIRD_PARTY_DIR) / "librequake/e3m4.map";
    const map::Level level = map::loadLevel(path.string());
    ASSERT_TRUE(level.hasPlayerStart);
    // The player start, 30 cm up: a ~3.75 m wide passage running along -z (8 free cells on
    // either side in x, 32 toward -z), with sloped and angled brushes around it.
    const Vec3 centre = level.playerStart + Vec3{0, 0.3, 0};
    SmokeSettings st = testlevels::small(48);
    SmokeVolume vol = SmokeVolume::create(level, {}, centre, st);
    const GridInfo& g = vol.grid();
    auto inGrid = [&](const map::LevelBrush& b) {
        const Vec3 mn = g.origin, mx = g.origin + g.size();
        return b.bounds.max.x > mn.x && b.bounds.min.x < mx.x && b.bounds.max.y > mn.y && b.bounds.min.y < mx.y &&
               b.bounds.max.z > mn.z && b.bounds.min.z < mx.z;
    };
    auto skewed = [&](const map::LevelBrush& b) {
        if (!inGrid(b)) return false;
        for (const auto& f : b.faces) {
            const Vec3& n = f.normal;
            const double m = std::max({std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)});
            if (m < 1 - 1e-6) return true;
        }
        return false;
    };
    const std::vector<ConvexHull> skewedHulls = hullsOf(level, skewed);
    const std::vector<ConvexHull> allHulls = hullsOf(level, inGrid);
    std::cout << "e3m4 at " << centre.x << " " << centre.y << " " << centre.z << ": " << allHulls.size()
              << " brushes in the grid, " << skewedHulls.size() << " not axis-aligned\n";
    ASSERT_GT(skewedHulls.size(), 0u) << "the test point should see some non-axis-aligned brushes";
    EXPECT_EQ(countLeakyPairs(vol, allHulls), 0);
    Rng rng(7);
    int inside = 0;
    for (const auto& h : skewedHulls) inside += countFreeCellsInside(vol, h, rng, 50);
    EXPECT_EQ(inside, 0);
    for (int i = 0; i < 45; ++i) vol.step(1.0 / 30);
    EXPECT_TRUE(densityOnlyInFluid(vol));
    std::string why;
    EXPECT_TRUE(vol.validate(&why)) << why;
    EXPECT_GT(vol.totalDensity(), 0.1);
}
