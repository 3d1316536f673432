// See physics_world.h.
#include "sim/physics_world.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace obscura::sim {

namespace {
// Bullet inflates convex hulls by their collision margin; its default 4 cm would keep the player
// visibly off walls and bullet hits off surfaces. 1 mm keeps GJK robust and is invisible.
constexpr btScalar kHullMargin = 0.001f;
// Level surfaces: rough stone/wood against a crate (Bullet multiplies the two frictions: 0.56).
constexpr btScalar kStaticFriction = 0.8f;
// Crates: wood on stone; a little bounce so a drop reads as a drop, and light damping so a
// pushed crate settles in about a second instead of drifting on float noise.
constexpr btScalar kCrateFriction = 0.7f, kCrateRestitution = 0.1f;
constexpr btScalar kCrateLinearDamping = 0.05f, kCrateAngularDamping = 0.1f;
// prop_crate defaults: a 0.75 m wooden crate of 20 kg (waist-high: jumpable, not steppable).
constexpr double kDefaultCrateSize = 0.75, kDefaultCrateMass = 20;
// Accepted crate ranges: below 5 cm the box is smaller than the solver's contact tolerances;
// beyond 10 m / 10 t it is level geometry, not a prop.
constexpr double kMinCrateSize = 0.05, kMaxCrateSize = 10, kMaxCrateMass = 10000;
// prop_barrel defaults: an empty oil drum, 0.3 m radius, 0.9 m tall, 12 kg (a rifle shot near
// its top tips it; a player can push it).
constexpr double kDefaultBarrelRadius = 0.3, kDefaultBarrelHeight = 0.9, kDefaultBarrelMass = 12;
// Projectiles (grenades): bounce a little (0.35: a steel canister on concrete), roll (friction
// 0.6) and settle: rolling friction and damping stop a rolling grenade within a few metres.
constexpr btScalar kProjectileRestitution = 0.35f, kProjectileFriction = 0.6f, kProjectileRollingFriction = 0.02f;
constexpr btScalar kProjectileLinearDamping = 0.1f, kProjectileAngularDamping = 0.3f;

std::string where(const map::Level& level, const map::SourcePos& pos) {
    return (level.sourcePath.empty() ? std::string("<level>") : level.sourcePath) + ":" + std::to_string(pos.line) +
           ":" + std::to_string(pos.column);
}

// A number key of an entity, or `fallback` if absent; throws if present but not a number in range.
double numberKey(const map::Level& level, const map::LevelEntity& e, const char* key, double fallback, double lo,
                 double hi, const char* unit) {
    if (!e.has(key)) return fallback;
    const std::string& text = e.value(key);
    double v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);  // locale-independent
    if (ec != std::errc() || ptr != end || !(v > lo && v <= hi))
        throw SimError(where(level, e.pos) + ": " + e.classname + " key '" + key + "' is '" + text +
                       "', expected a number of " + unit + " in (" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
}

btRigidBody::btRigidBodyConstructionInfo staticInfo(btCollisionShape* shape) {
    btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shape);
    info.m_friction = kStaticFriction;
    return info;
}

// Sweep results, keeping only surfaces the shape moves into: a shape resting against a wall or
// floor must be free to leave it (Bullet reports such contacts at fraction 0 otherwise).
// Collects every hit; m_closestHitFraction stays 1 so Bullet culls nothing.
struct ApproachingHits : btCollisionWorld::ConvexResultCallback {
    btVector3 direction;
    std::vector<SweepHit> hits;
    explicit ApproachingHits(const btVector3& dir) : direction(dir) {}
    btScalar addSingleResult(btCollisionWorld::LocalConvexResult& r, bool normalInWorldSpace) override {
        btVector3 n = normalInWorldSpace ? r.m_hitNormalLocal
                                         : r.m_hitCollisionObject->getWorldTransform().getBasis() * r.m_hitNormalLocal;
        if (n.length2() < btScalar(1e-12)) return btScalar(1);
        n.normalize();
        // Moving along a surface, within the noise of GJK's normals (1e-3, 0.06 degrees), is not
        // moving into it: otherwise a shape touching a floor could not slide along it.
        if (n.dot(direction) > btScalar(-1e-3)) return btScalar(1);
        SweepHit h;
        h.fraction = r.m_hitFraction;
        h.point = fromBt(r.m_hitPointLocal);  // Bullet stores the world-space point here
        h.normal = fromBt(n);
        h.dynamicBody = r.m_hitCollisionObject->getUserIndex();
        hits.push_back(h);
        return btScalar(1);  // keep the triangle-mesh cull at 1 too: every triangle hit is reported
    }
};
}  // namespace

struct PhysicsWorld::MeshData {
    std::vector<btScalar> vertices;
    std::vector<int> indices;
    btTriangleIndexVertexArray interface;
};

PhysicsWorld::PhysicsWorld(double gravity)
    : config_(std::make_unique<btDefaultCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(config_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()),
      world_(std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(), config_.get())) {
    world_->setGravity(btVector3(0, static_cast<btScalar>(-gravity), 0));
    // Box-on-hull contacts by SAT and face clipping (needs the shapes' polyhedral features): a full
    // four-point manifold, so a crate rests and slides flat instead of rocking on GJK's one new
    // point per step and sinking centimetres into the floor while pushed.
    world_->getDispatchInfo().m_enableSatConvex = true;
}

PhysicsWorld::~PhysicsWorld() {
    // Bodies leave the world before it dies; the members then die bodies first, shapes and meshes
    // after them, the world and its parts last (reverse declaration order).
    for (auto& [id, p] : projectiles_) world_->removeRigidBody(p.body.get());
    for (auto it = kinematic_.rbegin(); it != kinematic_.rend(); ++it) world_->removeRigidBody(it->get());
    for (auto it = dynamic_.rbegin(); it != dynamic_.rend(); ++it) world_->removeRigidBody(it->get());
    for (auto it = static_.rbegin(); it != static_.rend(); ++it) world_->removeRigidBody(it->get());
}

void PhysicsWorld::addLevel(const map::Level& level) {
    for (const auto& b : level.brushes)
        if (b.solid && !b.mover) addStaticHull(b.hullPoints, where(level, b.pos));
    for (const auto& e : level.entities) {
        if (e.classname != "prop_crate" && e.classname != "prop_barrel") continue;
        if (!e.hasOrigin) throw SimError(where(level, e.pos) + ": " + e.classname + " without an 'origin'");
        if (e.classname == "prop_crate") {
            const double size = numberKey(level, e, "size", kDefaultCrateSize, kMinCrateSize, kMaxCrateSize, "metres");
            const double mass = numberKey(level, e, "mass", kDefaultCrateMass, 0, kMaxCrateMass, "kg");
            const double h = size / 2;
            addDynamicBox(e.origin + Vec3{0, h, 0}, {h, h, h}, mass, e.yaw);
        } else {
            const double r = numberKey(level, e, "radius", kDefaultBarrelRadius, kMinCrateSize, kMaxCrateSize, "metres");
            const double height = numberKey(level, e, "height", kDefaultBarrelHeight, kMinCrateSize, kMaxCrateSize, "metres");
            const double mass = numberKey(level, e, "mass", kDefaultBarrelMass, 0, kMaxCrateMass, "kg");
            addDynamicCylinder(e.origin + Vec3{0, height / 2, 0}, r, height / 2, mass, e.yaw);
        }
    }
}

void PhysicsWorld::addStatic(std::unique_ptr<btCollisionShape> shape) {
    static_.push_back(std::make_unique<btRigidBody>(staticInfo(shape.get())));
    static_.back()->setUserIndex(-1);
    world_->addRigidBody(static_.back().get());
    shapes_.push_back(std::move(shape));
}

std::unique_ptr<btConvexHullShape> PhysicsWorld::makeHull(const std::vector<Vec3>& points, const std::string& whereFrom) const {
    map::Aabb box;
    for (const auto& p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw SimError(whereFrom + ": solid brush has a non-finite hull point");
        box.extend(p);
    }
    // A solid needs 4 points and some thickness in every axis (0.1 mm: below float resolution at
    // a few hundred metres from the origin).
    const Vec3 ext = box.empty() ? Vec3{} : box.max - box.min;
    if (points.size() < 4 || std::min({ext.x, ext.y, ext.z}) < 1e-4)
        throw SimError(whereFrom + ": solid brush is degenerate (" + std::to_string(points.size()) +
                       " hull points), cannot make a collider");
    auto hull = std::make_unique<btConvexHullShape>();
    for (const auto& p : points) hull->addPoint(toBt(p), false);
    hull->recalcLocalAabb();
    hull->setMargin(kHullMargin);
    hull->initializePolyhedralFeatures();
    return hull;
}

void PhysicsWorld::addStaticHull(const std::vector<Vec3>& points, const std::string& whereFrom) {
    addStatic(makeHull(points, whereFrom));
}

int PhysicsWorld::addKinematicHulls(const std::vector<std::vector<Vec3>>& hulls, int userIndex, const std::string& whereFrom) {
    // One child per brush at the identity: the hulls keep their world-space points, and the
    // body's transform is the mover's offset from where the level was built.
    auto compound = std::make_unique<btCompoundShape>();
    for (const auto& points : hulls) {
        auto hull = makeHull(points, whereFrom);
        compound->addChildShape(btTransform::getIdentity(), hull.get());
        shapes_.push_back(std::move(hull));
    }
    btRigidBody::btRigidBodyConstructionInfo info = staticInfo(compound.get());
    auto body = std::make_unique<btRigidBody>(info);
    // Kinematic: Bullet moves props resting on it with it and never moves it.
    body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
    body->setActivationState(DISABLE_DEACTIVATION);
    body->setUserIndex(userIndex);
    world_->addRigidBody(body.get());
    shapes_.push_back(std::move(compound));
    kinematic_.push_back(std::move(body));
    return static_cast<int>(kinematic_.size() - 1);
}

void PhysicsWorld::setKinematicOffset(int i, const Vec3& offset) {
    btRigidBody& body = *kinematic_.at(static_cast<std::size_t>(i));
    const btTransform t(btQuaternion::getIdentity(), toBt(offset));
    // The world transform only: Bullet's next step takes the kinematic velocity (for props riding
    // it) from the interpolation transform, the pose of the step before.
    body.setWorldTransform(t);
    world_->updateSingleAabb(&body);  // sweeps and contacts before the next Bullet step see it moved
}

void PhysicsWorld::addStaticTriangleMesh(const TriangleMesh& mesh) {
    if (mesh.indices.size() % 3 != 0)
        throw SimError("triangle mesh: " + std::to_string(mesh.indices.size()) + " indices, not a multiple of 3");
    for (std::size_t i = 0; i < mesh.indices.size(); ++i)
        if (mesh.indices[i] >= mesh.vertices.size())
            throw SimError("triangle mesh: index " + std::to_string(i) + " is " + std::to_string(mesh.indices[i]) +
                           ", but there are " + std::to_string(mesh.vertices.size()) + " vertices");
    if (mesh.indices.empty()) return;  // nothing to collide with
    auto data = std::make_unique<MeshData>();
    for (const auto& v : mesh.vertices) {
        data->vertices.push_back(static_cast<btScalar>(v.x));
        data->vertices.push_back(static_cast<btScalar>(v.y));
        data->vertices.push_back(static_cast<btScalar>(v.z));
    }
    data->indices.assign(mesh.indices.begin(), mesh.indices.end());
    btIndexedMesh part;
    part.m_numTriangles = static_cast<int>(data->indices.size() / 3);
    part.m_triangleIndexBase = reinterpret_cast<const unsigned char*>(data->indices.data());
    part.m_triangleIndexStride = 3 * sizeof(int);
    part.m_numVertices = static_cast<int>(mesh.vertices.size());
    part.m_vertexBase = reinterpret_cast<const unsigned char*>(data->vertices.data());
    part.m_vertexStride = 3 * sizeof(btScalar);
    data->interface.addIndexedMesh(part, PHY_INTEGER);
    auto shape = std::make_unique<btBvhTriangleMeshShape>(&data->interface, true);
    meshes_.push_back(std::move(data));
    addStatic(std::move(shape));
}

btRigidBody* PhysicsWorld::addDynamic(std::unique_ptr<btCollisionShape> shape, const Vec3& centre, double mass, double yaw) {
    btVector3 inertia(0, 0, 0);
    shape->calculateLocalInertia(static_cast<btScalar>(mass), inertia);
    const btTransform t(btQuaternion(btVector3(0, 1, 0), static_cast<btScalar>(yaw)), toBt(centre));
    auto motion = std::make_unique<btDefaultMotionState>(t);
    btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(mass), motion.get(), shape.get(), inertia);
    info.m_friction = kCrateFriction;
    info.m_restitution = kCrateRestitution;
    info.m_linearDamping = kCrateLinearDamping;
    info.m_angularDamping = kCrateAngularDamping;
    dynamic_.push_back(std::make_unique<btRigidBody>(info));
    const int index = static_cast<int>(dynamic_.size() - 1);
    dynamic_.back()->setUserIndex(index);
    world_->addRigidBody(dynamic_.back().get());
    shapes_.push_back(std::move(shape));
    motionStates_.push_back(std::move(motion));
    return dynamic_.back().get();
}

int PhysicsWorld::addDynamicBox(const Vec3& centre, const Vec3& halfExtents, double mass, double yaw) {
    auto shape = std::make_unique<btBoxShape>(toBt(halfExtents));
    shape->initializePolyhedralFeatures();
    addDynamic(std::move(shape), centre, mass, yaw);
    halfExtents_.push_back(halfExtents);
    bodyShapes_.push_back(BodyShape::Box);
    return static_cast<int>(dynamic_.size() - 1);
}

int PhysicsWorld::addDynamicCylinder(const Vec3& centre, double radius, double halfHeight, double mass, double yaw) {
    addDynamic(std::make_unique<btCylinderShape>(toBt(Vec3{radius, halfHeight, radius})), centre, mass, yaw);
    halfExtents_.push_back({radius, halfHeight, radius});
    bodyShapes_.push_back(BodyShape::Cylinder);
    return static_cast<int>(dynamic_.size() - 1);
}

int PhysicsWorld::addProjectile(const Vec3& centre, double radius, double mass, const Vec3& velocity) {
    Projectile p;
    p.shape = std::make_unique<btSphereShape>(static_cast<btScalar>(radius));
    btVector3 inertia(0, 0, 0);
    p.shape->calculateLocalInertia(static_cast<btScalar>(mass), inertia);
    p.motion = std::make_unique<btDefaultMotionState>(btTransform(btQuaternion::getIdentity(), toBt(centre)));
    btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(mass), p.motion.get(), p.shape.get(), inertia);
    info.m_friction = kProjectileFriction;
    info.m_rollingFriction = kProjectileRollingFriction;
    info.m_restitution = kProjectileRestitution;
    info.m_linearDamping = kProjectileLinearDamping;
    info.m_angularDamping = kProjectileAngularDamping;
    p.body = std::make_unique<btRigidBody>(info);
    p.body->setLinearVelocity(toBt(velocity));
    // Continuous collision: swept as a sphere of its radius once it moves more than half of it a tick.
    p.body->setCcdMotionThreshold(static_cast<btScalar>(radius * 0.5));
    p.body->setCcdSweptSphereRadius(static_cast<btScalar>(radius * 0.9));
    p.body->setUserIndex(-2);  // not a prop: rays report it as static-like (-1 is level geometry)
    p.body->setActivationState(DISABLE_DEACTIVATION);
    world_->addRigidBody(p.body.get());
    const int id = nextProjectile_++;
    projectiles_.emplace(id, std::move(p));
    return id;
}

void PhysicsWorld::removeProjectile(int id) {
    const auto it = projectiles_.find(id);
    if (it == projectiles_.end()) return;
    world_->removeRigidBody(it->second.body.get());
    projectiles_.erase(it);
}

std::vector<int> PhysicsWorld::projectileIds() const {
    std::vector<int> ids;
    for (const auto& [id, p] : projectiles_) ids.push_back(id);
    return ids;
}

void PhysicsWorld::step(double dt) {
    world_->stepSimulation(static_cast<btScalar>(dt), 1, static_cast<btScalar>(dt));
}

std::optional<RayHit> PhysicsWorld::rayCast(const Vec3& from, const Vec3& to) const {
    const btVector3 a = toBt(from), b = toBt(to);
    if (a == b) return std::nullopt;
    btCollisionWorld::ClosestRayResultCallback cb(a, b);
    world_->rayTest(a, b, cb);
    if (!cb.hasHit()) return std::nullopt;
    RayHit h;
    h.point = fromBt(cb.m_hitPointWorld);
    h.normal = normalize(fromBt(cb.m_hitNormalWorld));
    h.fraction = cb.m_closestHitFraction;
    h.dynamicBody = cb.m_collisionObject->getUserIndex();
    return h;
}

std::vector<SweepHit> PhysicsWorld::sweepAll(const btConvexShape& shape, const Vec3& from, const Vec3& to) const {
    const btVector3 a = toBt(from), b = toBt(to);
    if ((b - a).length2() < btScalar(1e-14)) return {};
    ApproachingHits cb((b - a).normalized());
    world_->convexSweepTest(&shape, btTransform(btQuaternion::getIdentity(), a), btTransform(btQuaternion::getIdentity(), b), cb);
    // Stable: ties keep the broadphase's (deterministic) order.
    std::stable_sort(cb.hits.begin(), cb.hits.end(),
                     [](const SweepHit& x, const SweepHit& y) { return x.fraction < y.fraction; });
    return std::move(cb.hits);
}

namespace {
struct ContactCollector : btCollisionWorld::ContactResultCallback {
    const btCollisionObject* self;
    std::vector<ShapeContact> found;
    ContactCollector(const btCollisionObject* me, double within) : self(me) {
        m_closestDistanceThreshold = static_cast<btScalar>(within);
    }
    btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper* a, int, int,
                             const btCollisionObjectWrapper* b, int, int) override {
        // m_normalWorldOnB points from B towards A.
        const bool selfIsA = a->getCollisionObject() == self;
        const btCollisionObject* other = selfIsA ? b->getCollisionObject() : a->getCollisionObject();
        const btVector3 n = selfIsA ? cp.m_normalWorldOnB : -cp.m_normalWorldOnB;
        if (n.length2() < btScalar(1e-12)) return 0;
        found.push_back({normalize(fromBt(n)), cp.getDistance(), other->getUserIndex()});
        return 0;
    }
};
}  // namespace

std::vector<ShapeContact> PhysicsWorld::contacts(const btConvexShape& shape, const Vec3& centre, double within) const {
    btCollisionObject probe;
    probe.setCollisionShape(const_cast<btConvexShape*>(&shape));  // Bullet's API is not const; it only reads
    probe.setWorldTransform(btTransform(btQuaternion::getIdentity(), toBt(centre)));
    ContactCollector cb(&probe, within);
    world_->contactTest(&probe, cb);
    return std::move(cb.found);
}

std::optional<SweepHit> PhysicsWorld::sweep(const btConvexShape& shape, const Vec3& from, const Vec3& to) const {
    auto hits = sweepAll(shape, from, to);
    if (hits.empty()) return std::nullopt;
    return hits.front();
}

}  // namespace obscura::sim
