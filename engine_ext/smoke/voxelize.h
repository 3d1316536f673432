// Conservative voxelisation of the level for the smoke grid: a cell is solid if its box overlaps a
// solid brush or a mesh triangle by more than a hair (touching does not count, so an axis-aligned
// wall on a cell boundary does not grow by a cell). Overlap is decided by the separating axis
// theorem, so a wall thinner than a cell, at any angle, still yields a closed layer of solid cells:
// two cells on opposite sides of a wall are never neighbours, not even diagonally (the segment
// between their centres lies in their two boxes and crosses the wall), which is what the solver's
// no-leak argument needs (see README.md).
#pragma once

#include <cstdint>
#include <vector>

#include "core/triangle_mesh.h"
#include "core/vec3.h"
#include "map/level.h"
#include "smoke/smoke_grid.h"

namespace obscura::smoke {

struct Plane {
    Vec3 normal;      // outward, unit
    double offset = 0;  // dot(normal, x) == offset on the plane
};

// A convex solid ready for box tests: its outward planes, its vertices, its edge directions.
struct ConvexHull {
    std::vector<Plane> planes;
    std::vector<Vec3> points;
    std::vector<Vec3> edges;  // unit directions (may repeat); empty when the brush has no faces
    map::Aabb bounds;
};

// From a compiled brush: planes from its faces when it has any, else from its hull points
// (every supporting plane through three of them), edges from its face polygons.
ConvexHull makeHull(const map::LevelBrush& brush);

// Separating axis test of the box [boxMin, boxMax] against the hull: box axes, hull planes and
// (when the hull has edges) edge x box-axis cross products. Overlap must exceed `epsilon` metres.
bool boxOverlapsHull(const Vec3& boxMin, const Vec3& boxMax, const ConvexHull& hull, double epsilon);

// Akenine-Moeller's triangle/box test (13 axes), with the same epsilon convention.
bool boxOverlapsTriangle(const Vec3& boxMin, const Vec3& boxMax, const Vec3& a, const Vec3& b, const Vec3& c,
                         double epsilon);

// Marks solid cells in `solid` (grid.cells() bytes, 0 = free): kVoxelBuilt for cells overlapping
// solid brushes (not movers' brushes: they move, see LevelBrush::mover) and mesh triangles, kVoxelOutside for cells whose centre lies outside the level's
// bounds (not built, but no smoke may go there). The flight to the light (self-shadow) is blocked
// by built cells only: above an open level's bounds is sky.
constexpr std::uint8_t kVoxelBuilt = 1;
constexpr std::uint8_t kVoxelOutside = 2;
void voxelizeLevel(const map::Level& level, const std::vector<TriangleMesh>& meshes, const GridInfo& grid,
                   std::vector<std::uint8_t>& solid);

}  // namespace obscura::smoke
