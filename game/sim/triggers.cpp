// See triggers.h. Follows id Software's triggers.qc (multi_trigger, multi_touch, teleport_touch,
// trigger_push_touch) and subs.qc (SUB_UseTargets), read, not copied.
#include "sim/triggers.h"

#include "map/map_compile.h"

#include <algorithm>
#include <cmath>

namespace obscura::sim {

namespace {
constexpr double kMultipleWait = 0.2;      // s: trigger_multiple's default wait
constexpr double kTeleportEnabled = 0.2;   // s: a targeted teleporter works this long after its use
constexpr double kPushDefaultSpeed = 1000;  // trigger_push's `speed`; the velocity is 10 x it, in u/s
constexpr double kPushScale = 10;
constexpr double kMaxVelocity = 2000;       // u/s per axis: Quake's sv_maxvelocity caps the push
// info_teleport_destination's origin is raised 27 u at spawn and the player's origin (24 u above
// its feet) is put there: the feet land 3 u above the mark.
constexpr double kTeleportFeetAbove = 27 - 24;
constexpr int kNoTouch = 1, kPushOnce = 1;  // spawnflags
constexpr double kHurtDefaultDamage = 5;    // trigger_hurt's `dmg`
constexpr double kHurtInterval = 1;         // s: hurt_touch turns itself off this long after a hurt
// Firings that fire more (a relay naming itself) stop this deep: a level loop cannot hang a tick.
constexpr int kMaxFireDepth = 16;

bool startsWith(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

bool overlaps(const map::Aabb& a, const map::Aabb& b) {
    return a.min.x <= b.max.x && a.max.x >= b.min.x && a.min.y <= b.max.y && a.max.y >= b.min.y && a.min.z <= b.max.z &&
           a.max.z >= b.min.z;
}

Vec3 yawForward(double yaw) { return {-std::sin(yaw), 0, -std::cos(yaw)}; }  // the player's convention
}  // namespace

Triggers::Triggers(const map::Level& level, double tickRate, const EntityKeys& keys)
    : level_(level), keys_(keys), tickRate_(tickRate) {
    auto named = [&](const std::string& name) {
        for (const auto& e : level.entities)
            if (e.value("targetname") == name) return true;
        return false;
    };
    std::vector<std::string> unsimulated;  // warned once a class, at its first entity
    for (std::size_t ei = 0; ei < level.entities.size(); ++ei) {
        const map::LevelEntity& e = level.entities[ei];
        for (const char* key : {"target", "killtarget"})
            if (e.has(key) && !e.value(key).empty() && !named(e.value(key)) && e.classname != "path_corner")
                keys.warn(e, std::string("'") + key + "' '" + e.value(key) + "' names no entity");
        const std::string& c = e.classname;
        Trigger t;
        if (c == "trigger_once" || c == "trigger_secret") t.kind = Kind::Once;  // trigger_secret: a once that counts a secret
        else if (c == "trigger_multiple") t.kind = Kind::Multiple;
        else if (c == "trigger_relay") t.kind = Kind::Relay;
        else if (c == "trigger_counter") t.kind = Kind::Counter;
        else if (c == "trigger_teleport") t.kind = Kind::Teleport;
        else if (c == "trigger_push") t.kind = Kind::Push;
        else if (c == "trigger_hurt") t.kind = Kind::Hurt;
        else if (c == "trigger_changelevel") t.kind = Kind::ChangeLevel;
        else {
            if (startsWith(c, "trigger_") && std::find(unsimulated.begin(), unsimulated.end(), c) == unsimulated.end()) {
                unsimulated.push_back(c);
                keys.warn(e, "is not simulated; this and every other " + c + " are ignored");
            }
            continue;
        }
        t.entity = static_cast<int>(ei);
        t.targetname = e.value("targetname");
        for (const auto& b : level.brushes)
            if (b.entityIndex == t.entity) t.box.extend(b.bounds.min), t.box.extend(b.bounds.max);
        const int flags = keys.spawnflags(e);
        const bool used = t.kind == Kind::Relay || t.kind == Kind::Counter;  // by name only, no volume
        t.touchable = !used && !t.box.empty();
        if (!used && t.box.empty()) keys.warn(e, "has no brushes; it can never be touched");
        if (t.kind == Kind::Counter) t.count = std::max(1, static_cast<int>(keys.number(e, "count", 2)));
        if (t.kind == Kind::Once || t.kind == Kind::Multiple) {
            if (flags & kNoTouch) t.touchable = false;
            if (e.has("health")) keys.warn(e, "'health' (shootable triggers) is ignored");
            const double wait = keys.number(e, "wait", 0);
            t.wait = t.kind == Kind::Once ? -1 : std::max(1L, std::lround((wait > 0 ? wait : kMultipleWait) * tickRate));
            if (keys.hasDirection(e)) t.directional = true, t.facing = keys.moveDirection(e);
        }
        if (t.kind == Kind::Teleport) {
            const std::string& to = e.value("target");
            for (std::size_t d = 0; d < level.entities.size() && t.destination < 0; ++d)
                if (level.entities[d].hasOrigin && !to.empty() && level.entities[d].value("targetname") == to)
                    t.destination = static_cast<int>(d);
            if (t.destination < 0) keys.warn(e, "no info_teleport_destination named '" + to + "'; it does nothing");
        }
        if (t.kind == Kind::Push) {
            const double speed = keys.positive(e, "speed", kPushDefaultSpeed);
            const Vec3 v = keys.moveDirection(e) * (speed * kPushScale);
            auto cap = [](double x) { return std::clamp(x, -kMaxVelocity, kMaxVelocity); };
            t.push = Vec3{cap(v.x), cap(v.y), cap(v.z)} / keys.unitsPerMetre();
            t.pushOnce = (flags & kPushOnce) != 0;
        }
        if (t.kind == Kind::Hurt) {
            t.damage = std::max(0, static_cast<int>(std::lround(keys.number(e, "dmg", kHurtDefaultDamage))));
            t.wait = std::max(1L, std::lround(kHurtInterval * tickRate));
        }
        if (t.kind == Kind::ChangeLevel && e.value("map").empty()) keys.warn(e, "has no 'map'; touching it ends the level with no next map");
        triggers_.push_back(t);
    }
}

bool Triggers::touching(const Trigger& t, const PlayerState& p, double r) const {
    map::Aabb b;
    b.extend(p.feet - Vec3{r, 0, r});
    b.extend(p.feet + Vec3{r, static_cast<double>(p.height), r});
    return overlaps(t.box, b);
}

// multi_trigger: fires unless still waiting; a trigger_once is removed once fired.
void Triggers::multiTrigger(Trigger& t, std::vector<int>& fired) {
    if (t.removed || t.cooldown > 0) return;
    fired.push_back(t.entity);
    if (t.wait > 0) t.cooldown = t.wait;
    else t.removed = true;
}

void Triggers::use(const std::string& targetname, std::vector<int>& fired) {
    if (targetname.empty()) return;
    for (auto& t : triggers_) {
        if (t.removed || t.targetname != targetname) continue;
        if (t.kind == Kind::Once || t.kind == Kind::Multiple) multiTrigger(t, fired);
        else if (t.kind == Kind::Relay) fired.push_back(t.entity);
        else if (t.kind == Kind::Counter && --t.count == 0) {  // counter_use: fires on the last use, once
            t.removed = true;
            fired.push_back(t.entity);
        } else if (t.kind == Kind::Teleport) t.cooldown = std::max(1L, std::lround(kTeleportEnabled * tickRate_));
    }
}

void Triggers::fire(const std::vector<int>& fired, Movers& movers) {
    for (int f : fired) useTargets(f, movers);
}

void Triggers::useTargets(int entity, Movers& movers) {
    const double delay = keys_.number(level_.entities[static_cast<std::size_t>(entity)], "delay", 0);
    if (delay > 0) pending_.push_back({std::max(1L, std::lround(delay * tickRate_)), entity});
    else useNow(entity, movers, 0);
}

// SUB_UseTargets (after any delay): kill the `killtarget` triggers, use everything named `target`.
void Triggers::useNow(int entity, Movers& movers, int depth) {
    const map::LevelEntity& e = level_.entities[static_cast<std::size_t>(entity)];
    if (!e.value("message").empty()) messages_.push_back(entity);
    const std::string& kill = e.value("killtarget");
    if (!kill.empty())
        for (auto& t : triggers_)
            if (t.targetname == kill) t.removed = true;
    const std::string& target = e.value("target");
    if (target.empty() || e.classname == "trigger_teleport") return;  // a teleporter's target is its destination
    std::vector<int> fired;
    movers.use(target, fired);
    use(target, fired);
    if (depth + 1 >= kMaxFireDepth) return;
    for (int f : fired) {
        const double delay = keys_.number(level_.entities[static_cast<std::size_t>(f)], "delay", 0);
        if (delay > 0) pending_.push_back({std::max(1L, std::lround(delay * tickRate_)), f});
        else useNow(f, movers, depth + 1);
    }
}

void Triggers::step(PlayerState& player, double radius, PhysicsWorld& physics, Movers& movers, std::vector<SimEvent>& events) {
    std::vector<int> fired;
    for (auto& t : triggers_) {
        if (t.cooldown > 0) --t.cooldown;
        if (t.removed || !t.touchable) continue;
        if (t.kind == Kind::Push) {  // grenades too, as trigger_push_touch does
            for (int id : physics.projectileIds()) {
                btRigidBody& g = physics.projectile(id);
                map::Aabb p;
                p.extend(fromBt(g.getWorldTransform().getOrigin()));
                if (overlaps(t.box, p)) g.setLinearVelocity(toBt(t.push));
            }
        }
        if (!touching(t, player, radius)) continue;
        switch (t.kind) {
        case Kind::Once:
        case Kind::Multiple:
            // multi_touch: an angle lets it fire only for a player facing that way.
            if (t.directional && dot(yawForward(player.yaw), t.facing) < 0) break;
            multiTrigger(t, fired);
            break;
        case Kind::Teleport: {
            if (t.destination < 0 || (!t.targetname.empty() && t.cooldown == 0)) break;
            const map::LevelEntity& d = level_.entities[static_cast<std::size_t>(t.destination)];
            // The horizontal speed goes on along the new yaw (Quake sets 300 u/s forward).
            const double speed = std::hypot(player.velocity.x, player.velocity.z);
            player.feet = d.origin + Vec3{0, kTeleportFeetAbove / keys_.unitsPerMetre(), 0};
            player.yaw = static_cast<float>(d.yaw);
            player.velocity = yawForward(d.yaw) * speed;
            player.onGround = false;
            SimEvent ev = SimEvent::at(SimEventType::Teleport, player.feet);
            ev.id = t.entity;
            events.push_back(ev);
            break;
        }
        case Kind::Push:
            player.velocity = t.push;
            if (t.pushOnce) t.removed = true;
            break;
        case Kind::Hurt:  // hurt_touch: the damage, then off for a second
            if (t.cooldown > 0) break;
            player.health -= t.damage;
            t.cooldown = t.wait;
            break;
        case Kind::ChangeLevel: {  // changelevel_touch: its targets fire, then the level ends (once)
            t.removed = true;
            fired.push_back(t.entity);
            SimEvent ev = SimEvent::at(SimEventType::ChangeLevel, player.feet);
            ev.id = t.entity;
            events.push_back(ev);
            break;
        }
        case Kind::Relay:
        case Kind::Counter: break;
        }
    }
    // Delayed firings that come due, oldest first.
    std::vector<int> due;
    for (auto& p : pending_)
        if (--p.ticks == 0) due.push_back(p.entity);
    pending_.erase(std::remove_if(pending_.begin(), pending_.end(), [](const Pending& p) { return p.ticks <= 0; }), pending_.end());
    for (int e : due) useNow(e, movers, 0);
    fire(fired, movers);
}

void Triggers::takeMessages(std::vector<SimEvent>& events) {
    for (int entity : messages_) {
        SimEvent ev;
        ev.type = SimEventType::Message;
        ev.id = entity;
        events.push_back(ev);
    }
    messages_.clear();
}

void Triggers::hash(StateHasher& h) const {
    for (const auto& t : triggers_) {
        h.add(static_cast<std::uint64_t>(t.cooldown));
        h.add(t.removed);
        h.add(static_cast<std::int32_t>(t.count));
    }
    for (const auto& p : pending_) {
        h.add(static_cast<std::uint64_t>(p.ticks));
        h.add(static_cast<std::int32_t>(p.entity));
    }
}

}  // namespace obscura::sim
