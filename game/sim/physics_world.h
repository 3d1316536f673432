// The Bullet world, owned RAII: collision configuration, dispatcher, broadphase, solver, world,
// and every shape, mesh, motion state and body created through it (bodies leave the world before
// anything they point at dies). Static level geometry: one btConvexHullShape per solid brush,
// btBvhTriangleMeshShape for misc_model triangles. Dynamic props: `prop_crate` boxes and
// `prop_barrel` cylinders. Projectiles (grenades): spheres with continuous collision detection,
// added and removed during play. Plus the queries the game needs: convex sweeps (the player's
// capsule) and rays (hitscan).
// Stepped with a fixed dt and one substep, Bullet 3.24 is bit-identical run to run.
#pragma once

#include "core/triangle_mesh.h"
#include "core/vec3.h"
#include "map/level.h"

#include <btBulletDynamicsCommon.h>

#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace obscura::sim {

using obscura::TriangleMesh;

// Bad input to the simulation (a malformed level or mesh); the message names file:line:column.
struct SimError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline btVector3 toBt(const Vec3& v) {
    return {static_cast<btScalar>(v.x), static_cast<btScalar>(v.y), static_cast<btScalar>(v.z)};
}
inline Vec3 fromBt(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

// Bodies of moving brushes (sim/movers.h) carry this user index minus the mover's index: below
// every other kind (props >= 0, level -1, projectiles -2), so code that tells props apart by
// `>= 0` treats a mover like level geometry.
constexpr int kMoverUserIndexBase = -1000;
inline int moverUserIndex(int mover) { return kMoverUserIndexBase - mover; }
inline bool isMoverUserIndex(int userIndex) { return userIndex <= kMoverUserIndexBase; }

struct RayHit {
    Vec3 point;
    Vec3 normal;            // unit, facing the ray's origin
    double fraction = 1;    // 0..1 along the ray
    int dynamicBody = -1;   // index of the dynamic body hit, -1 for static geometry, -2 a projectile, moverUserIndex
};

struct SweepHit {
    double fraction = 1;  // 0..1 along the sweep
    Vec3 point;           // contact point on the surface hit
    Vec3 normal;          // unit surface normal at the hit, pointing at the swept shape
    int dynamicBody = -1;
};

struct ShapeContact {
    Vec3 normal;          // unit, pushing the shape out of (away from) what it touches
    double distance = 0;  // gap between the surfaces; negative when overlapping
    int dynamicBody = -1;
};

// Gravity (m/s^2) on the dynamic bodies: crates, barrels, grenades. 20, not Quake's 25 (800 u/s^2,
// the player's, PlayerTuning::gravity) nor 9.81: the grenade throw speeds, the crates' friction
// against the player's push and the recorded replays were tuned at 20.
constexpr double kBodyGravity = 20;

class PhysicsWorld {
public:
    explicit PhysicsWorld(double gravity);
    ~PhysicsWorld();
    PhysicsWorld(const PhysicsWorld&) = delete;
    PhysicsWorld& operator=(const PhysicsWorld&) = delete;

    // A level's colliders: a convex hull per solid brush (non-solid and mover brushes are skipped:
    // movers add their own kinematic bodies, addKinematicHulls) and a box per
    // `prop_crate` entity (keys `size` in metres, default 0.75, and `mass` in kg, default 20; the
    // origin marks the crate's base). Throws SimError naming level.sourcePath:line:column.
    void addLevel(const map::Level& level);
    // `where` names the source for error messages ("file:line:column").
    void addStaticHull(const std::vector<Vec3>& points, const std::string& where = "hull");
    // World-space triangles (misc_model colliders). Throws SimError on an out-of-range index.
    void addStaticTriangleMesh(const TriangleMesh& mesh);
    // A kinematic body (a mover): one convex hull per point set (world space at rest, each checked
    // like a static hull), moved by setKinematicOffset. Its user index is `userIndex`. Returns its index.
    int addKinematicHulls(const std::vector<std::vector<Vec3>>& hulls, int userIndex, const std::string& where);
    // Places kinematic body `i` at its rest pose translated by `offset` (bodies never rotate).
    void setKinematicOffset(int i, const Vec3& offset);
    std::size_t kinematicBodyCount() const { return kinematic_.size(); }

    enum class BodyShape { Box, Cylinder };
    // Returns the index of the new dynamic body.
    int addDynamicBox(const Vec3& centre, const Vec3& halfExtents, double mass, double yaw);
    // An upright cylinder (Y axis): radius, half height.
    int addDynamicCylinder(const Vec3& centre, double radius, double halfHeight, double mass, double yaw);

    // A projectile: a sphere with continuous collision detection (it never tunnels through a thin
    // wall at throwing speed). Returns its id; ids are never reused.
    int addProjectile(const Vec3& centre, double radius, double mass, const Vec3& velocity);
    void removeProjectile(int id);
    btRigidBody& projectile(int id) const { return *projectiles_.at(id).body; }
    // Ids of the live projectiles, oldest first.
    std::vector<int> projectileIds() const;

    void step(double dt);

    // Closest hit along the segment, or nothing.
    std::optional<RayHit> rayCast(const Vec3& from, const Vec3& to) const;
    // Sweeps `shape` (convex, unrotated, e.g. the player's capsule) from centre `from` to `to`:
    // the closest surface the shape moves *into*. Surfaces it touches and moves along (within
    // 0.06 degrees) or away from are ignored, so a shape resting on a floor or against a wall is
    // always free to leave it.
    std::optional<SweepHit> sweep(const btConvexShape& shape, const Vec3& from, const Vec3& to) const;
    // Every such hit (one per convex body or triangle), closest first.
    std::vector<SweepHit> sweepAll(const btConvexShape& shape, const Vec3& from, const Vec3& to) const;
    // Surfaces overlapping `shape` (unrotated, at `centre`) or nearer than `within` metres.
    std::vector<ShapeContact> contacts(const btConvexShape& shape, const Vec3& centre, double within) const;

    std::size_t staticBodyCount() const { return static_.size(); }
    std::size_t dynamicBodyCount() const { return dynamic_.size(); }
    btRigidBody& dynamicBody(std::size_t i) const { return *dynamic_.at(i); }
    Vec3 dynamicHalfExtents(std::size_t i) const { return halfExtents_.at(i); }
    BodyShape dynamicShape(std::size_t i) const { return bodyShapes_.at(i); }

private:
    void addStatic(std::unique_ptr<btCollisionShape> shape);
    std::unique_ptr<btConvexHullShape> makeHull(const std::vector<Vec3>& points, const std::string& whereFrom) const;

    std::unique_ptr<btDefaultCollisionConfiguration> config_;
    std::unique_ptr<btCollisionDispatcher> dispatcher_;
    std::unique_ptr<btDbvtBroadphase> broadphase_;
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
    std::unique_ptr<btDiscreteDynamicsWorld> world_;

    // Destroyed in reverse order of declaration: bodies first, then what they reference.
    struct MeshData;
    std::vector<std::unique_ptr<MeshData>> meshes_;
    std::vector<std::unique_ptr<btCollisionShape>> shapes_;
    std::vector<std::unique_ptr<btDefaultMotionState>> motionStates_;
    std::vector<std::unique_ptr<btRigidBody>> static_;
    std::vector<std::unique_ptr<btRigidBody>> dynamic_;
    std::vector<std::unique_ptr<btRigidBody>> kinematic_;
    std::vector<Vec3> halfExtents_;
    std::vector<BodyShape> bodyShapes_;
    struct Projectile {
        std::unique_ptr<btSphereShape> shape;
        std::unique_ptr<btDefaultMotionState> motion;
        std::unique_ptr<btRigidBody> body;
    };
    std::map<int, Projectile> projectiles_;  // by id: iteration in creation order
    int nextProjectile_ = 0;
    btRigidBody* addDynamic(std::unique_ptr<btCollisionShape> shape, const Vec3& centre, double mass, double yaw);
};

}  // namespace obscura::sim
