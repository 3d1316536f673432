// Brush -> convex polygons. Each face's three points define a plane whose normal
// normalize(cross(p3 - p1, p2 - p1)) points out of the brush (qbsp's convention); the brush is
// the intersection of the planes' back half-spaces. Each face polygon is a huge quad on its plane
// clipped by every other plane. Texture coordinates follow Quake's TextureAxisFromPlane
// projection for classic faces and the explicit axes for Valve-220 faces.
// All in map units and Quake axes; map_compile.cpp converts to metres and Y-up.
#pragma once

#include "map/map_parser.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace obscura::map {

struct BrushPolygon {
    std::vector<Vec3> points;  // convex, counter-clockwise seen from outside
    std::vector<double> u, v;  // texels per point
    Vec3 normal;               // outward, unit
    int faceIndex = 0;
};

struct Plane {
    Vec3 normal;  // unit
    double dist = 0;  // dot(normal, p) = dist on the plane
};

std::optional<Plane> planeFromPoints(const Vec3& p1, const Vec3& p2, const Vec3& p3);

// The brush's polygons, or an error message (brush skipped by the caller) if the brush is
// invalid: fewer than 4 planes, a degenerate face, or no closed volume.
struct BrushResult {
    std::vector<BrushPolygon> polygons;
    std::string error;  // empty when valid
};
BrushResult buildBrush(const MapBrush& brush);

// Texel coordinates of point p on a face (Quake or Valve-220 projection).
void faceTexel(const MapFace& face, const Vec3& normal, const Vec3& p, double& u, double& v);

}  // namespace obscura::map
