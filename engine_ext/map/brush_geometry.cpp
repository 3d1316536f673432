// See brush_geometry.h.
#include "map/brush_geometry.h"

#include <cmath>

namespace obscura::map {

namespace {
// Points closer than this to a plane (map units) count as on it. Map coordinates are integers or
// TrenchBroom's 1e-5-accurate decimals; 1e-3 absorbs that noise without merging real detail.
constexpr double kPlaneEpsilon = 1e-3;
// Half size of the initial quad on each face plane (map units): 2^20, far beyond any Quake map
// (+-4096 in id's qbsp, +-32768 in later ports) and still exact to ~1e-10 in doubles.
constexpr double kHugeHalfSize = 1048576.0;
// A polygon corner farther out than this (map units) survived from the initial quad: the planes
// do not close the brush. 2^18 leaves a valid brush room up to about +-150,000 units.
constexpr double kMaxCorner = 262144.0;
// Welding distance for consecutive polygon points (map units).
constexpr double kWeldEpsilon = 1e-4;

using Polygon = std::vector<Vec3>;

// Keeps the part of `poly` behind `plane` (dot(n,p) - d <= 0).
Polygon clipBehind(const Polygon& poly, const Plane& plane) {
    Polygon out;
    const std::size_t n = poly.size();
    if (n == 0) return out;
    std::vector<double> d(n);
    bool anyFront = false, anyBack = false;
    for (std::size_t i = 0; i < n; ++i) {
        d[i] = dot(plane.normal, poly[i]) - plane.dist;
        anyFront |= d[i] > kPlaneEpsilon;
        anyBack |= d[i] < -kPlaneEpsilon;
    }
    if (!anyFront) return poly;
    if (!anyBack) return out;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& a = poly[i];
        const Vec3& b = poly[(i + 1) % n];
        const double da = d[i], db = d[(i + 1) % n];
        if (da <= kPlaneEpsilon) out.push_back(a);
        if ((da > kPlaneEpsilon && db < -kPlaneEpsilon) || (da < -kPlaneEpsilon && db > kPlaneEpsilon)) {
            const double t = da / (da - db);
            out.push_back(a + (b - a) * t);
        }
    }
    return out;
}

Polygon weld(const Polygon& poly) {
    Polygon out;
    for (const auto& p : poly)
        if (out.empty() || length(p - out.back()) > kWeldEpsilon) out.push_back(p);
    while (out.size() > 1 && length(out.front() - out.back()) <= kWeldEpsilon) out.pop_back();
    return out;
}

double area(const Polygon& poly, const Vec3& normal) {
    Vec3 sum;
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) sum += cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
    return 0.5 * dot(sum, normal);
}

// Quake's TextureAxisFromPlane (qbsp/map.c): the base axis pair of the closest cardinal plane.
void quakeTextureAxes(const Vec3& normal, Vec3& xv, Vec3& yv) {
    static const Vec3 base[18] = {{0, 0, 1},  {1, 0, 0}, {0, -1, 0}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0},
                                  {1, 0, 0},  {0, 1, 0}, {0, 0, -1}, {-1, 0, 0}, {0, 1, 0}, {0, 0, -1},
                                  {0, 1, 0},  {1, 0, 0}, {0, 0, -1}, {0, -1, 0}, {1, 0, 0}, {0, 0, -1}};
    double best = 0;
    int bestAxis = 0;
    for (int i = 0; i < 6; ++i) {
        const double d = dot(normal, base[i * 3]);
        if (d > best) {
            best = d;
            bestAxis = i;
        }
    }
    xv = base[bestAxis * 3 + 1];
    yv = base[bestAxis * 3 + 2];
}

double component(const Vec3& v, int i) { return i == 0 ? v.x : (i == 1 ? v.y : v.z); }
void setComponent(Vec3& v, int i, double x) { (i == 0 ? v.x : (i == 1 ? v.y : v.z)) = x; }
}  // namespace

std::optional<Plane> planeFromPoints(const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    const Vec3 n = cross(p3 - p1, p2 - p1);
    const double len = length(n);
    if (!(len > 1e-9)) return std::nullopt;
    Plane pl;
    pl.normal = n / len;
    pl.dist = dot(pl.normal, p1);
    return pl;
}

void faceTexel(const MapFace& f, const Vec3& normal, const Vec3& p, double& u, double& v) {
    const double su = f.uScale == 0 ? 1 : f.uScale, sv = f.vScale == 0 ? 1 : f.vScale;
    if (f.valve220) {
        u = dot(p, f.uAxis) / su + f.uOffset;
        v = dot(p, f.vAxis) / sv + f.vOffset;
        return;
    }
    Vec3 xv, yv;
    quakeTextureAxes(normal, xv, yv);
    // Rotation, exact for the right angles (as qbsp does).
    double sinv, cosv;
    if (f.rotation == 0) { sinv = 0; cosv = 1; }
    else if (f.rotation == 90) { sinv = 1; cosv = 0; }
    else if (f.rotation == 180) { sinv = 0; cosv = -1; }
    else if (f.rotation == 270) { sinv = -1; cosv = 0; }
    else {
        const double a = f.rotation / 180.0 * 3.14159265358979323846;
        sinv = std::sin(a);
        cosv = std::cos(a);
    }
    const int s = xv.x != 0 ? 0 : (xv.y != 0 ? 1 : 2);
    const int t = yv.x != 0 ? 0 : (yv.y != 0 ? 1 : 2);
    for (Vec3* vec : {&xv, &yv}) {
        const double ns = cosv * component(*vec, s) - sinv * component(*vec, t);
        const double nt = sinv * component(*vec, s) + cosv * component(*vec, t);
        setComponent(*vec, s, ns);
        setComponent(*vec, t, nt);
    }
    u = dot(p, xv) / su + f.uOffset;
    v = dot(p, yv) / sv + f.vOffset;
}

BrushResult buildBrush(const MapBrush& brush) {
    BrushResult r;
    if (brush.faces.size() < 4) {
        r.error = "brush has " + std::to_string(brush.faces.size()) + " faces, a closed brush needs at least 4";
        return r;
    }
    std::vector<Plane> planes;
    for (std::size_t i = 0; i < brush.faces.size(); ++i) {
        const auto& f = brush.faces[i];
        auto pl = planeFromPoints(f.points[0], f.points[1], f.points[2]);
        if (!pl) {
            r.error = "face " + std::to_string(i + 1) + " (line " + std::to_string(f.pos.line) + ") has collinear points";
            return r;
        }
        planes.push_back(*pl);
    }
    for (std::size_t i = 0; i < planes.size(); ++i) {
        const Plane& pl = planes[i];
        // Start from a huge quad on the plane, counter-clockwise seen from outside.
        const Vec3 ref = std::fabs(pl.normal.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
        const Vec3 u = normalize(cross(ref, pl.normal)) * kHugeHalfSize;
        const Vec3 v = cross(pl.normal, normalize(u)) * kHugeHalfSize;
        const Vec3 c = pl.normal * pl.dist;
        Polygon poly = {c - u - v, c + u - v, c + u + v, c - u + v};
        for (std::size_t j = 0; j < planes.size() && !poly.empty(); ++j) {
            if (j == i) continue;
            // A duplicate plane: the earlier face keeps the polygon.
            if (dot(planes[j].normal, pl.normal) > 1 - 1e-9 && std::fabs(planes[j].dist - pl.dist) < kPlaneEpsilon) {
                if (j < i) poly.clear();
                continue;
            }
            poly = clipBehind(poly, planes[j]);
        }
        poly = weld(poly);
        if (poly.size() < 3 || area(poly, pl.normal) < 1e-6) continue;  // clipped away: a redundant plane
        BrushPolygon bp;
        bp.normal = pl.normal;
        bp.faceIndex = static_cast<int>(i);
        for (const auto& p : poly) {
            double tu, tv;
            faceTexel(brush.faces[i], pl.normal, p, tu, tv);
            bp.points.push_back(p);
            bp.u.push_back(tu);
            bp.v.push_back(tv);
        }
        r.polygons.push_back(std::move(bp));
    }
    if (r.polygons.size() < 4) {
        r.polygons.clear();
        r.error = "brush encloses no volume (its planes leave fewer than 4 faces)";
        return r;
    }
    for (const auto& bp : r.polygons)
        for (const auto& p : bp.points)
            if (std::fabs(p.x) > kMaxCorner || std::fabs(p.y) > kMaxCorner || std::fabs(p.z) > kMaxCorner) {
                r.polygons.clear();
                r.error = "brush is not closed (its planes leave it unbounded) or lies beyond +-262144 units";
                return r;
            }
    return r;
}

}  // namespace obscura::map
