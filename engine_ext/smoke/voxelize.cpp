#include "smoke/voxelize.h"

#include <algorithm>
#include <cmath>

namespace obscura::smoke {
namespace {

constexpr double kPlaneTolerance = 1e-7;  // metres: hull points within this of a plane count as on it

void projectPoints(const std::vector<Vec3>& pts, const Vec3& axis, double& lo, double& hi) {
    lo = 1e300;
    hi = -1e300;
    for (const Vec3& p : pts) {
        const double d = dot(p, axis);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
}

// Half the box's extent along `axis` (the box's projection radius).
double boxRadius(const Vec3& half, const Vec3& axis) {
    return half.x * std::fabs(axis.x) + half.y * std::fabs(axis.y) + half.z * std::fabs(axis.z);
}

void addPlanesFromPoints(ConvexHull& hull) {
    const auto& p = hull.points;
    const std::size_t n = p.size();
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a + 1; b < n; ++b)
            for (std::size_t c = b + 1; c < n; ++c) {
                Vec3 nrm = cross(p[b] - p[a], p[c] - p[a]);
                const double len = length(nrm);
                if (len < 1e-12) continue;
                nrm = nrm / len;
                bool front = false, back = false;
                for (const Vec3& q : p) {
                    const double s = dot(nrm, q - p[a]);
                    front |= s > kPlaneTolerance;
                    back |= s < -kPlaneTolerance;
                }
                if (front && back) continue;  // not a supporting plane
                if (front) nrm = -nrm;        // make it outward: every point behind
                hull.planes.push_back({nrm, dot(nrm, p[a])});
            }
}

}  // namespace

ConvexHull makeHull(const map::LevelBrush& brush) {
    ConvexHull hull;
    hull.points = brush.hullPoints;
    for (const auto& face : brush.faces) {
        if (face.vertices.empty()) continue;
        const Vec3 n = normalize(face.normal);
        hull.planes.push_back({n, dot(n, face.vertices[0].position)});
        for (std::size_t i = 0; i < face.vertices.size(); ++i) {
            const Vec3 e = face.vertices[(i + 1) % face.vertices.size()].position - face.vertices[i].position;
            if (length(e) > 1e-9) hull.edges.push_back(normalize(e));
        }
        if (brush.hullPoints.empty())
            for (const auto& v : face.vertices) hull.points.push_back(v.position);
    }
    if (hull.planes.empty()) addPlanesFromPoints(hull);
    for (const Vec3& q : hull.points) hull.bounds.extend(q);
    return hull;
}

bool boxOverlapsHull(const Vec3& boxMin, const Vec3& boxMax, const ConvexHull& hull, double epsilon) {
    if (hull.points.empty()) return false;
    // Box axes.
    if (hull.bounds.min.x > boxMax.x - epsilon || hull.bounds.max.x < boxMin.x + epsilon) return false;
    if (hull.bounds.min.y > boxMax.y - epsilon || hull.bounds.max.y < boxMin.y + epsilon) return false;
    if (hull.bounds.min.z > boxMax.z - epsilon || hull.bounds.max.z < boxMin.z + epsilon) return false;
    const Vec3 centre = (boxMin + boxMax) * 0.5, half = (boxMax - boxMin) * 0.5;
    // Hull face planes: separated when the whole box is in front of one.
    for (const Plane& pl : hull.planes)
        if (dot(pl.normal, centre) - boxRadius(half, pl.normal) > pl.offset - epsilon) return false;
    // Edge x box-axis cross products.
    static const Vec3 kAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const Vec3& e : hull.edges)
        for (const Vec3& b : kAxes) {
            Vec3 axis = cross(e, b);
            const double len = length(axis);
            if (len < 1e-9) continue;
            axis = axis / len;
            double lo, hi;
            projectPoints(hull.points, axis, lo, hi);
            const double c = dot(axis, centre), r = boxRadius(half, axis);
            if (lo > c + r - epsilon || hi < c - r + epsilon) return false;
        }
    return true;
}

bool boxOverlapsTriangle(const Vec3& boxMin, const Vec3& boxMax, const Vec3& a, const Vec3& b, const Vec3& c,
                         double epsilon) {
    const Vec3 centre = (boxMin + boxMax) * 0.5, half = (boxMax - boxMin) * 0.5;
    const Vec3 v[3] = {a - centre, b - centre, c - centre};
    const std::vector<Vec3> tri = {v[0], v[1], v[2]};
    auto separatedOn = [&](const Vec3& axis) {
        const double len = length(axis);
        if (len < 1e-12) return false;
        const Vec3 n = axis / len;
        double lo, hi;
        projectPoints(tri, n, lo, hi);
        const double r = boxRadius(half, n);
        return lo > r - epsilon || hi < -r + epsilon;
    };
    static const Vec3 kAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const Vec3& ax : kAxes)
        if (separatedOn(ax)) return false;
    const Vec3 e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    // The triangle's plane: a zero-thickness surface, so no epsilon shrink here (a triangle lying
    // exactly on a cell face still marks the cell: meshes have no inside to be conservative about).
    {
        const Vec3 n = normalize(cross(e[0], e[1]));
        if (length(n) > 0 && std::fabs(dot(n, v[0])) > boxRadius(half, n)) return false;
    }
    for (const Vec3& ed : e)
        for (const Vec3& ax : kAxes)
            if (separatedOn(cross(ed, ax))) return false;
    return true;
}

void voxelizeLevel(const map::Level& level, const std::vector<TriangleMesh>& meshes, const GridInfo& grid,
                   std::vector<std::uint8_t>& solid) {
    solid.assign(grid.cells(), 0);
    const double h = grid.cellSize;
    const double eps = 1e-6 * h;  // "touching is not overlapping": a wall on a cell boundary stays one side
    auto cellRange = [&](const map::Aabb& b, int lo[3], int hi[3]) {
        const Vec3 mn = (b.min - grid.origin) / h, mx = (b.max - grid.origin) / h;
        const int n[3] = {grid.nx, grid.ny, grid.nz};
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::max(0, static_cast<int>(std::floor(mn[a])) - 1);
            hi[a] = std::min(n[a] - 1, static_cast<int>(std::floor(mx[a])) + 1);
        }
        return lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2];
    };
    auto cellBox = [&](int i, int j, int k, Vec3& mn, Vec3& mx) {
        mn = grid.origin + Vec3{i * h, j * h, k * h};
        mx = mn + Vec3{h, h, h};
    };

    // Outside the level's bounds: solid (nothing was built there; the safest assumption).
    for (int k = 0; k < grid.nz; ++k)
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i) {
                const Vec3 c = grid.cellCentre(i, j, k);
                const auto& lb = level.bounds;
                if (lb.empty() || c.x < lb.min.x || c.y < lb.min.y || c.z < lb.min.z || c.x > lb.max.x ||
                    c.y > lb.max.y || c.z > lb.max.z)
                    solid[grid.index(i, j, k)] = kVoxelOutside;
            }

    // Marks every not-yet-solid cell of the range [lo, hi] whose box `overlaps`.
    auto mark = [&](const int lo[3], const int hi[3], const auto& overlaps) {
        for (int k = lo[2]; k <= hi[2]; ++k)
            for (int j = lo[1]; j <= hi[1]; ++j)
                for (int i = lo[0]; i <= hi[0]; ++i) {
                    std::uint8_t& s = solid[grid.index(i, j, k)];
                    if (s == kVoxelBuilt) continue;
                    Vec3 mn, mx;
                    cellBox(i, j, k, mn, mx);
                    if (overlaps(mn, mx)) s = kVoxelBuilt;
                }
    };
    for (const auto& brush : level.brushes) {
        // Movers (doors, plats) are not static: the game passes them as moving obstacles where
        // they are now (game/smoke_obstacles.cpp), so an open door lets the smoke through.
        if (!brush.solid || brush.mover) continue;
        const ConvexHull hull = makeHull(brush);
        int lo[3], hi[3];
        if (hull.points.empty() || !cellRange(hull.bounds, lo, hi)) continue;
        mark(lo, hi, [&](const Vec3& mn, const Vec3& mx) { return boxOverlapsHull(mn, mx, hull, eps); });
    }

    for (const auto& mesh : meshes) {
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const std::uint32_t ia = mesh.indices[t], ib = mesh.indices[t + 1], ic = mesh.indices[t + 2];
            if (ia >= mesh.vertices.size() || ib >= mesh.vertices.size() || ic >= mesh.vertices.size()) continue;
            const Vec3 &a = mesh.vertices[ia], &b = mesh.vertices[ib], &c = mesh.vertices[ic];
            map::Aabb tb;
            tb.extend(a);
            tb.extend(b);
            tb.extend(c);
            int lo[3], hi[3];
            if (!cellRange(tb, lo, hi)) continue;
            mark(lo, hi, [&](const Vec3& mn, const Vec3& mx) { return boxOverlapsTriangle(mn, mx, a, b, c, eps); });
        }
    }
}

}  // namespace obscura::smoke
