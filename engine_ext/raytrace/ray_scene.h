// Triangles in an Embree 3 scene (CPU, single precision inside Embree): the closest hit and the
// occlusion test the ray-traced references need. Thread-safe for queries once built.
#pragma once

#include "core/triangle_mesh.h"
#include "core/vec3.h"

#include <memory>
#include <vector>

namespace obscura {

class RayScene {
public:
    explicit RayScene(const std::vector<TriangleMesh>& meshes);
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // Anything along o + t d for tnear < t < tfar (d need not be unit: t is in its lengths)?
    bool occluded(const Vec3& o, const Vec3& d, double tnear, double tfar) const;
    // The nearest hit along o + t d, t in (tnear, tfar): its t and geometric normal (not unit,
    // either side); false when there is none.
    bool intersect(const Vec3& o, const Vec3& d, double tnear, double tfar, double& t, Vec3& normal) const;
    // The same, naming what it hit: the mesh's index in the constructor's list and the triangle's in it.
    struct Hit {
        double t = 0;
        Vec3 normal;
        unsigned mesh = 0, triangle = 0;
    };
    bool intersect(const Vec3& o, const Vec3& d, double tnear, double tfar, Hit& hit) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace obscura
