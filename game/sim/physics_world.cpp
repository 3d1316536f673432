// See physics_world.h.
#include "sim/physics_world.h"

#include <cmath>

namespace obscura::sim {

namespace {
// Bullet inflates convex hulls by their collision margin; its default 4 cm would keep the player
// visibly off walls and bullet hits off surfaces. 1 mm keeps GJK robust and is invisible.
constexpr btScalar kHullMargin = 0.001f;

btRigidBody* makeStatic(btCollisionShape* shape) {
    btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shape);
    info.m_friction = 0.8f;
    auto* body = new btRigidBody(info);
    return body;
}
}  // namespace

PhysicsWorld::PhysicsWorld(double gravity)
    : config_(std::make_unique<btDefaultCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(config_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()),
      world_(std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(), config_.get())) {
    world_->setGravity(btVector3(0, static_cast<btScalar>(-gravity), 0));
}

PhysicsWorld::~PhysicsWorld() {
    // Bodies leave the world before their shapes, meshes and motion states die.
    for (auto& b : dynamic_) world_->removeRigidBody(b.get());
    for (auto& b : static_) world_->removeRigidBody(b.get());
}

void PhysicsWorld::addStaticHull(const std::vector<Vec3>& points) {
    if (points.size() < 4) return;
    auto hull = std::make_unique<btConvexHullShape>();
    for (const auto& p : points) hull->addPoint(toBt(p), false);
    hull->recalcLocalAabb();
    hull->setMargin(kHullMargin);
    static_.emplace_back(makeStatic(hull.get()));
    world_->addRigidBody(static_.back().get());
    shapes_.push_back(std::move(hull));
}

void PhysicsWorld::addStaticTriangleMesh(const TriangleMesh& mesh) {
    if (mesh.indices.size() < 3) return;
    auto verts = std::make_unique<std::vector<btScalar>>();
    for (const auto& v : mesh.vertices) {
        verts->push_back(static_cast<btScalar>(v.x));
        verts->push_back(static_cast<btScalar>(v.y));
        verts->push_back(static_cast<btScalar>(v.z));
    }
    auto idx = std::make_unique<std::vector<int>>(mesh.indices.begin(), mesh.indices.end());
    btIndexedMesh part;
    part.m_numTriangles = static_cast<int>(idx->size() / 3);
    part.m_triangleIndexBase = reinterpret_cast<const unsigned char*>(idx->data());
    part.m_triangleIndexStride = 3 * sizeof(int);
    part.m_numVertices = static_cast<int>(mesh.vertices.size());
    part.m_vertexBase = reinterpret_cast<const unsigned char*>(verts->data());
    part.m_vertexStride = 3 * sizeof(btScalar);
    auto iface = std::make_unique<btTriangleIndexVertexArray>();
    iface->addIndexedMesh(part, PHY_INTEGER);
    auto shape = std::make_unique<btBvhTriangleMeshShape>(iface.get(), true);
    static_.emplace_back(makeStatic(shape.get()));
    world_->addRigidBody(static_.back().get());
    shapes_.push_back(std::move(shape));
    meshInterfaces_.push_back(std::move(iface));
    meshVertices_.push_back(std::move(verts));
    meshIndices_.push_back(std::move(idx));
}

int PhysicsWorld::addDynamicBox(const Vec3& centre, const Vec3& halfExtents, double mass, double yaw) {
    auto shape = std::make_unique<btBoxShape>(toBt(halfExtents));
    btVector3 inertia(0, 0, 0);
    shape->calculateLocalInertia(static_cast<btScalar>(mass), inertia);
    btTransform t(btQuaternion(btVector3(0, 1, 0), static_cast<btScalar>(yaw)), toBt(centre));
    auto motion = std::make_unique<btDefaultMotionState>(t);
    btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(mass), motion.get(), shape.get(), inertia);
    info.m_friction = 0.7f;
    info.m_restitution = 0.1f;
    info.m_linearDamping = 0.05f;
    info.m_angularDamping = 0.1f;
    dynamic_.emplace_back(std::make_unique<btRigidBody>(info));
    world_->addRigidBody(dynamic_.back().get());
    halfExtents_.push_back(halfExtents);
    shapes_.push_back(std::move(shape));
    motionStates_.push_back(std::move(motion));
    return static_cast<int>(dynamic_.size() - 1);
}

void PhysicsWorld::step(double dt) {
    world_->stepSimulation(static_cast<btScalar>(dt), 1, static_cast<btScalar>(dt));
}

int PhysicsWorld::dynamicIndexOf(const btCollisionObject* o) const {
    for (std::size_t i = 0; i < dynamic_.size(); ++i)
        if (dynamic_[i].get() == o) return static_cast<int>(i);
    return -1;
}

std::optional<RayHit> PhysicsWorld::rayCast(const Vec3& from, const Vec3& to) const {
    btCollisionWorld::ClosestRayResultCallback cb(toBt(from), toBt(to));
    world_->rayTest(toBt(from), toBt(to), cb);
    if (!cb.hasHit()) return std::nullopt;
    RayHit h;
    h.point = fromBt(cb.m_hitPointWorld);
    h.normal = fromBt(cb.m_hitNormalWorld.normalized());
    h.fraction = cb.m_closestHitFraction;
    h.dynamicBody = dynamicIndexOf(cb.m_collisionObject);
    return h;
}

namespace {
// Closest hit, ignoring surfaces the sweep moves away from or along: a shape resting against a
// wall or floor must be free to leave it (Bullet reports such contacts at fraction 0 otherwise).
struct ApproachingResultCallback : btCollisionWorld::ClosestConvexResultCallback {
    btVector3 direction;
    ApproachingResultCallback(const btVector3& from, const btVector3& to)
        : ClosestConvexResultCallback(from, to), direction((to - from).normalized()) {}
    btScalar addSingleResult(btCollisionWorld::LocalConvexResult& r, bool normalInWorldSpace) override {
        const btVector3 n = normalInWorldSpace ? r.m_hitNormalLocal
                                               : r.m_hitCollisionObject->getWorldTransform().getBasis() * r.m_hitNormalLocal;
        // -0.01: moving along a surface (dot ~ 0) is not approaching it.
        if (n.dot(direction) > btScalar(-0.01)) return btScalar(1);
        return ClosestConvexResultCallback::addSingleResult(r, normalInWorldSpace);
    }
};
}  // namespace

std::optional<SweepHit> PhysicsWorld::sweep(const btConvexShape& shape, const Vec3& from, const Vec3& to) const {
    if (length(to - from) < 1e-9) return std::nullopt;
    const btTransform a(btQuaternion::getIdentity(), toBt(from)), b(btQuaternion::getIdentity(), toBt(to));
    ApproachingResultCallback cb(a.getOrigin(), b.getOrigin());
    world_->convexSweepTest(&shape, a, b, cb);
    if (!cb.hasHit()) return std::nullopt;
    SweepHit h;
    h.fraction = cb.m_closestHitFraction;
    h.normal = normalize(fromBt(cb.m_hitNormalWorld));
    h.dynamicBody = dynamicIndexOf(cb.m_hitCollisionObject);
    return h;
}

}  // namespace obscura::sim
