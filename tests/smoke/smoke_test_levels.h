// Small hand-built levels for the smoke tests: boxes (and rotated slabs) as solid brushes with
// faces, so the voxeliser's plane and edge tests are exercised.
#pragma once

#include <cmath>
#include <vector>

#include "map/level.h"
#include "smoke/smoke_volume.h"

namespace obscura::smoke::testlevels {

// A convex brush from its 8 corners (given as a box's corners in the order i&1 -> x, i&2 -> y,
// i&4 -> z, possibly transformed), with its six quad faces and outward normals.
inline map::LevelBrush hexahedron(const Vec3 (&p)[8]) {
    map::LevelBrush b;
    for (const Vec3& q : p) {
        b.hullPoints.push_back(q);
        b.bounds.extend(q);
    }
    Vec3 centre;
    for (const Vec3& q : p) centre += q;
    centre = centre / 8.0;
    // Quads as corner indices (any winding: normals are oriented outward below).
    const int quads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
        map::LevelPolygon poly;
        Vec3 n = normalize(cross(p[q[1]] - p[q[0]], p[q[2]] - p[q[0]]));
        if (dot(n, p[q[0]] - centre) < 0) n = -n;
        for (int v = 0; v < 4; ++v) poly.vertices.push_back({p[q[v]], n, 0, 0});
        poly.normal = n;
        b.faces.push_back(poly);
    }
    b.solid = true;
    return b;
}

inline map::LevelBrush box(const Vec3& mn, const Vec3& mx) {
    Vec3 p[8];
    for (int i = 0; i < 8; ++i) p[i] = {i & 1 ? mx.x : mn.x, i & 2 ? mx.y : mn.y, i & 4 ? mx.z : mn.z};
    return hexahedron(p);
}

// A box of half extents `half` rotated by `yaw` radians about +Y around `centre`.
inline map::LevelBrush rotatedBox(const Vec3& centre, const Vec3& half, double yaw) {
    Vec3 p[8];
    const double c = std::cos(yaw), s = std::sin(yaw);
    for (int i = 0; i < 8; ++i) {
        const Vec3 l{i & 1 ? half.x : -half.x, i & 2 ? half.y : -half.y, i & 4 ? half.z : -half.z};
        p[i] = centre + Vec3{c * l.x + s * l.z, l.y, -s * l.x + c * l.z};
    }
    return hexahedron(p);
}

inline void finish(map::Level& l) {
    l.entities.resize(1);
    l.entities[0].classname = "worldspawn";
    l.bounds = {};
    for (const auto& b : l.brushes) {
        l.bounds.extend(b.bounds.min);
        l.bounds.extend(b.bounds.max);
    }
}

// A closed room: inner space [mn, mx], walls `t` metres thick.
inline void addRoom(map::Level& l, const Vec3& mn, const Vec3& mx, double t) {
    l.brushes.push_back(box({mn.x - t, mn.y - t, mn.z - t}, {mx.x + t, mn.y, mx.z + t}));  // floor
    l.brushes.push_back(box({mn.x - t, mx.y, mn.z - t}, {mx.x + t, mx.y + t, mx.z + t}));  // ceiling
    l.brushes.push_back(box({mn.x - t, mn.y, mn.z - t}, {mn.x, mx.y, mx.z + t}));          // -x wall
    l.brushes.push_back(box({mx.x, mn.y, mn.z - t}, {mx.x + t, mx.y, mx.z + t}));          // +x wall
    l.brushes.push_back(box({mn.x, mn.y, mn.z - t}, {mx.x, mx.y, mn.z}));                  // -z wall
    l.brushes.push_back(box({mn.x, mn.y, mx.z}, {mx.x, mx.y, mx.z + t}));                  // +z wall
}

// The same room without its ceiling: open to the sky (the light reaches in from above).
inline map::Level openRoom(const Vec3& mn, const Vec3& mx, double t = 0.25) {
    map::Level l;
    addRoom(l, mn, mx, t);
    l.brushes.erase(l.brushes.begin() + 1);  // addRoom's second brush is the ceiling
    finish(l);
    return l;
}

inline map::Level closedRoom(const Vec3& mn, const Vec3& mx, double t = 0.25) {
    map::Level l;
    addRoom(l, mn, mx, t);
    finish(l);
    return l;
}

// Two rooms side by side along x (inner space x in [-3.5, 3.5], y in [0, 2.5], z in [-1.5, 1.5]),
// joined by a 1 m wide, 2 m high doorway in the 0.2 m wall at x = 0.
inline map::Level doorwayRooms() {
    map::Level l;
    addRoom(l, {-3.5, 0, -1.5}, {3.5, 2.5, 1.5}, 0.25);
    l.brushes.push_back(box({-0.1, 0, -1.5}, {0.1, 2.5, -0.5}));  // wall left of the door
    l.brushes.push_back(box({-0.1, 0, 0.5}, {0.1, 2.5, 1.5}));    // wall right of it
    l.brushes.push_back(box({-0.1, 2.0, -0.5}, {0.1, 2.5, 0.5}));  // lintel
    finish(l);
    return l;
}

// A wide floor under a high ceiling (80 x 15 x 80 m): open space for a whole cloud.
inline map::Level openFloor() {
    map::Level l;
    l.brushes.push_back(box({-40, -1, -40}, {40, 0, 40}));
    l.brushes.push_back(box({-40, 14, -40}, {40, 15, 40}));
    finish(l);
    return l;
}

// Smaller, faster settings for tests: 24^3 cells of 0.25 m (6 m box) unless told otherwise.
inline SmokeSettings small(int resolution = 24, int threads = 2) {
    SmokeSettings s;
    s.resolution = resolution;
    s.threads = threads;
    return s;
}

// The 5 x 2.75 x 5 m closed room most solver tests release smoke in (built once).
inline const map::Level& standardRoom() {
    static const map::Level l = closedRoom({-2.5, 0, -2.5}, {2.5, 2.75, 2.5});
    return l;
}

}  // namespace obscura::smoke::testlevels
