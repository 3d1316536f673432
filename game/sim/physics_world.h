// The Bullet world, owned RAII: collision configuration, dispatcher, broadphase, solver, world,
// and every shape, motion state and body created through it (destroyed in reverse order).
// Static level geometry: one convex hull per solid brush, triangle meshes for misc_models.
// Dynamic props: boxes. Plus the queries the game needs (capsule sweeps, rays).
// Stepped with a fixed dt and one substep, Bullet 3.24 is bit-identical run to run.
#pragma once

#include "core/triangle_mesh.h"
#include "core/vec3.h"

#include <btBulletDynamicsCommon.h>

#include <memory>
#include <optional>
#include <vector>

namespace obscura::sim {

inline btVector3 toBt(const Vec3& v) {
    return {static_cast<btScalar>(v.x), static_cast<btScalar>(v.y), static_cast<btScalar>(v.z)};
}
inline Vec3 fromBt(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

struct RayHit {
    Vec3 point;
    Vec3 normal;
    double fraction = 1;
    int dynamicBody = -1;  // index of the dynamic body hit, or -1 for static geometry
};

struct SweepHit {
    double fraction = 1;  // 0..1 along the sweep
    Vec3 normal;          // surface normal at the hit, pointing at the swept shape
    int dynamicBody = -1;
};

class PhysicsWorld {
public:
    explicit PhysicsWorld(double gravity);
    ~PhysicsWorld();
    PhysicsWorld(const PhysicsWorld&) = delete;
    PhysicsWorld& operator=(const PhysicsWorld&) = delete;

    void addStaticHull(const std::vector<Vec3>& points);
    void addStaticTriangleMesh(const TriangleMesh& mesh);
    // Returns the index of the new dynamic body.
    int addDynamicBox(const Vec3& centre, const Vec3& halfExtents, double mass, double yaw);

    void step(double dt);

    std::optional<RayHit> rayCast(const Vec3& from, const Vec3& to) const;
    // Sweeps `shape` (a convex shape, e.g. the player's capsule) from `from` to `to` (centres).
    std::optional<SweepHit> sweep(const btConvexShape& shape, const Vec3& from, const Vec3& to) const;

    std::size_t dynamicBodyCount() const { return dynamic_.size(); }
    btRigidBody& dynamicBody(std::size_t i) const { return *dynamic_[i]; }
    Vec3 dynamicHalfExtents(std::size_t i) const { return halfExtents_[i]; }
    int dynamicIndexOf(const btCollisionObject* o) const;

private:
    std::unique_ptr<btDefaultCollisionConfiguration> config_;
    std::unique_ptr<btCollisionDispatcher> dispatcher_;
    std::unique_ptr<btDbvtBroadphase> broadphase_;
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
    std::unique_ptr<btDiscreteDynamicsWorld> world_;

    std::vector<std::unique_ptr<btCollisionShape>> shapes_;
    std::vector<std::unique_ptr<btTriangleIndexVertexArray>> meshInterfaces_;
    std::vector<std::unique_ptr<std::vector<btScalar>>> meshVertices_;
    std::vector<std::unique_ptr<std::vector<int>>> meshIndices_;
    std::vector<std::unique_ptr<btDefaultMotionState>> motionStates_;
    std::vector<std::unique_ptr<btRigidBody>> static_;
    std::vector<std::unique_ptr<btRigidBody>> dynamic_;
    std::vector<Vec3> halfExtents_;
};

}  // namespace obscura::sim
