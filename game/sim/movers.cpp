// See movers.h. The QuakeC functions each part follows are named beside it (read in id Software's
// doors.qc, plats.qc and buttons.qc, GPL; nothing copied).
#include "sim/movers.h"

#include "map/map_compile.h"
#include "sim/pickups.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace obscura::sim {

namespace {
// Quake's defaults, in map units (u) and seconds; converted with the level's units per metre.
constexpr double kDoorSpeed = 100, kDoorWait = 3, kDoorLip = 8;      // func_door
constexpr double kButtonSpeed = 40, kButtonWait = 1, kButtonLip = 4;  // func_button
constexpr double kPlatSpeed = 150, kPlatTopWait = 3, kPlatLip = 8;    // func_plat: rests its height - 8 u below
constexpr double kPlatStayOnTop = 1;  // s: a player still on a raised plat keeps it up this long more
constexpr double kPlatInset = 25;     // u: the plat's inside trigger is 25 u in from its sides
constexpr double kPlatSmall = 50;     // u: narrower than this, the trigger is a 1 u strip at the centre
constexpr double kSecretSpeed = 50, kSecretWait = 5, kSecretPause = 1;  // func_door_secret (speed is fixed)
constexpr double kTrainSpeed = 100, kTrainCornerPause = 0.1;  // func_train: 0.1 s at a corner with no wait
constexpr double kDoorFieldXY = 60, kDoorFieldZ = 8;          // u: the door trigger field around a door group
constexpr double kDoorFieldRepeat = 1;                        // s: the field fires at most once a second
// Door spawnflags (doors.qc), secret door spawnflags.
constexpr int kDoorStartOpen = 1, kDoorDontLink = 4, kDoorGoldKey = 8, kDoorSilverKey = 16, kDoorToggle = 32;
constexpr double kKeyDoorRepeat = 2;  // s: door_touch speaks again after this (attack_finished)
constexpr int kSecretOpenOnce = 1, kSecret1stLeft = 2, kSecret1stDown = 4, kSecretNoShoot = 8, kSecretYesShoot = 16;
// Boxes that share a face touch (Quake's EntitiesTouching is inclusive); 1 micrometre of slack
// absorbs the rounding of coordinates divided by the units per metre.
constexpr double kTouchSlack = 1e-6;
// A shot's impact point lies on the brush's surface; 2 cm covers the hull margin and float noise.
constexpr double kShotSlack = 0.02;
// The player box touches a button 2 cm away: the controller keeps a 5 mm skin, so walking into a
// button never makes the boxes overlap exactly.
constexpr double kTouchReach = 0.02;
// A push that would leave the player more than 1 cm inside something is a crush (the mover is
// blocked); shallower overlaps are float noise the controller's depenetration removes.
constexpr double kCrushDepth = 0.01;

bool overlaps(const map::Aabb& a, const map::Aabb& b, double slack = 0) {
    return a.min.x <= b.max.x + slack && a.max.x >= b.min.x - slack && a.min.y <= b.max.y + slack &&
           a.max.y >= b.min.y - slack && a.min.z <= b.max.z + slack && a.max.z >= b.min.z - slack;
}
map::Aabb moved(map::Aabb b, const Vec3& d) {
    b.min += d;
    b.max += d;
    return b;
}
map::Aabb grown(map::Aabb b, const Vec3& g) {
    b.min -= g;
    b.max += g;
    return b;
}
map::Aabb playerBox(const PlayerState& p, double radius) {
    map::Aabb b;
    b.extend(p.feet - Vec3{radius, 0, radius});
    b.extend(p.feet + Vec3{radius, static_cast<double>(p.height), radius});
    return b;
}
// |d . size| in Quake's axes (movedir * size in QuakeC): a world direction and a world box.
double extentAlong(const Vec3& dir, const map::Aabb& box) {
    const Vec3 e = box.max - box.min;
    return std::fabs(dot(EntityKeys::toQuake(dir), Vec3{e.x, e.z, e.y}));
}
}  // namespace

Movers::Movers(const map::Level& level, PhysicsWorld& physics, double tickRate, const EntityKeys& keys)
    : level_(level), physics_(physics), keys_(keys), tickRate_(tickRate) {
    for (std::size_t ei = 0; ei < level.entities.size(); ++ei) {
        const map::LevelEntity& e = level.entities[ei];
        if (!map::isMoverClass(e.classname)) continue;
        Mover m;
        m.entity = static_cast<int>(ei);
        std::vector<std::vector<Vec3>> hulls;
        for (const auto& b : level.brushes) {
            if (b.entityIndex != m.entity) continue;
            m.brushes.push_back(b.bounds);
            m.bounds.extend(b.bounds.min);
            m.bounds.extend(b.bounds.max);
            if (b.solid) hulls.push_back(b.hullPoints);
        }
        if (hulls.empty()) {
            keys.warn(e, m.brushes.empty() ? "has no brushes; ignored" : "has no solid brushes; ignored");
            continue;
        }
        const int index = static_cast<int>(movers_.size());
        const std::string where = (level.sourcePath.empty() ? std::string("<level>") : level.sourcePath) + ":" +
                                  std::to_string(e.pos.line) + ":" + std::to_string(e.pos.column);
        m.body = physics.addKinematicHulls(hulls, moverUserIndex(index), where);
        m.targetname = e.value("targetname");
        m.master = index;
        if (e.classname == "func_door") buildDoor(m, e);
        else if (e.classname == "func_button") buildButton(m, e);
        else if (e.classname == "func_plat") buildPlat(m, e);
        else if (e.classname == "func_door_secret") buildSecret(m, e);
        else buildTrain(m, e);
        movers_.push_back(std::move(m));
    }
    linkDoors();
    for (const Mover& m : movers_) physics_.setKinematicOffset(m.body, m.s.offset);
}

// Doors and buttons (QuakeC's door and button spawn functions): `speed` (units a second), `wait`
// (seconds; 0 takes the class's) and a far end pos2 = movedir * (|movedir . size| - lip), each
// key's 0 or absence taking the class's default.
void Movers::slideAlongAngle(Mover& m, const map::LevelEntity& e, double speed, double wait, double lip) {
    const double upm = keys_.unitsPerMetre();
    m.speed = keys_.positive(e, "speed", speed) / upm / tickRate_;
    const double w = keys_.number(e, "wait", 0);
    m.wait = std::lround((w == 0 ? wait : w) * tickRate_);
    const double l = keys_.number(e, "lip", 0);
    const Vec3 dir = keys_.moveDirection(e);
    m.pos2 = dir * (extentAlong(dir, m.bounds) - (l == 0 ? lip : l) / upm);
}

// func_door: START_OPEN swaps the two ends.
void Movers::buildDoor(Mover& m, const map::LevelEntity& e) {
    m.kind = MoverKind::Door;
    slideAlongAngle(m, e, kDoorSpeed, kDoorWait, kDoorLip);
    const int flags = keys_.spawnflags(e);
    m.toggle = (flags & kDoorToggle) != 0;
    // A key door (sim/pickups.h): no trigger field, opened by touch with its key, then stays open.
    m.keys = (flags & kDoorSilverKey ? kSilverKey : 0) | (flags & kDoorGoldKey ? kGoldKey : 0);
    if (m.keys) m.wait = -1;
    if (flags & kDoorStartOpen) {
        std::swap(m.pos1, m.pos2);
        m.s.offset = m.pos1;
    }
    m.shootable = keys_.number(e, "health", 0) > 0;
    m.s.phase = Bottom;
}

// func_button: like a door with lip 4, speed 40, wait 1; fires its targets once pressed in.
void Movers::buildButton(Mover& m, const map::LevelEntity& e) {
    m.kind = MoverKind::Button;
    slideAlongAngle(m, e, kButtonSpeed, kButtonWait, kButtonLip);
    m.shootable = keys_.number(e, "health", 0) > 0;
    m.s.phase = Bottom;
}

// func_plat: built at the top, rests `height` (else its own height - 8 u) lower; rises when the
// player is in its inside trigger (plat_spawn_inside_trigger), waits 3 s on top, goes down.
// A targeted plat starts at the top and goes down for good when used.
void Movers::buildPlat(Mover& m, const map::LevelEntity& e) {
    const double upm = keys_.unitsPerMetre();
    m.kind = MoverKind::Plat;
    m.speed = keys_.positive(e, "speed", kPlatSpeed) / upm / tickRate_;
    m.wait = std::lround(kPlatTopWait * tickRate_);
    const double height = keys_.positive(e, "height", 0) / upm;
    const double travel = height > 0 ? height : (m.bounds.max.y - m.bounds.min.y) - kPlatLip / upm;
    m.pos2 = {0, -travel, 0};
    map::Aabb t = m.bounds;
    t.min.x += kPlatInset / upm, t.max.x -= kPlatInset / upm;
    t.min.z += kPlatInset / upm, t.max.z -= kPlatInset / upm;
    t.max.y = m.bounds.max.y + kPlatLip / upm;
    t.min.y = t.max.y - (travel + kPlatLip / upm);
    if (m.bounds.max.x - m.bounds.min.x <= kPlatSmall / upm)
        t.min.x = (m.bounds.min.x + m.bounds.max.x) / 2, t.max.x = t.min.x + 1 / upm;
    if (m.bounds.max.z - m.bounds.min.z <= kPlatSmall / upm)
        t.min.z = (m.bounds.min.z + m.bounds.max.z) / 2, t.max.z = t.min.z + 1 / upm;
    m.field = true;
    m.fieldBox = t;
    if (m.targetname.empty()) {
        m.s.offset = m.pos2;
        m.s.phase = Bottom;
    } else {
        m.s.phase = Up;  // waits at the top to be used (plat_use)
    }
}

// func_door_secret (fd_secret_use): sideways by t_width (or down), 1 s, back by t_length along
// its angle, `wait` s (5; OPEN_ONCE: for good), the same way home with a 1 s pause. Speed 50.
void Movers::buildSecret(Mover& m, const map::LevelEntity& e) {
    const double upm = keys_.unitsPerMetre();
    m.kind = MoverKind::SecretDoor;
    if (e.has("speed")) keys_.warn(e, "'speed' is ignored: secret doors move at 50 u/s, as in Quake");
    m.speed = kSecretSpeed / upm / tickRate_;
    const double wait = keys_.number(e, "wait", 0);
    m.wait = std::lround((wait == 0 ? kSecretWait : wait) * tickRate_);
    const int flags = keys_.spawnflags(e);
    Vec3 forward, right;
    keys_.yawVectors(e, forward, right);
    const Vec3 up{0, 1, 0};
    const bool down = (flags & kSecret1stDown) != 0;
    double width = keys_.number(e, "t_width", 0) / upm;
    if (width == 0) width = extentAlong(down ? up : right, m.bounds);
    double length = keys_.number(e, "t_length", 0) / upm;
    if (length == 0) length = extentAlong(forward, m.bounds);
    m.dest1 = down ? up * -width : right * (width * ((flags & kSecret1stLeft) ? -1.0 : 1.0));
    m.dest2 = m.dest1 + forward * length;
    m.pos2 = m.dest2;
    m.openOnce = (flags & kSecretOpenOnce) != 0;
    m.shootable = (m.targetname.empty() || (flags & kSecretYesShoot)) && !(flags & kSecretNoShoot);
    m.s.step = 0;
}

// func_train (train_find): its lowest corner (Quake's mins) sits on the path_corner `target`.
void Movers::buildTrain(Mover& m, const map::LevelEntity& e) {
    m.kind = MoverKind::Train;
    m.speed = keys_.positive(e, "speed", kTrainSpeed) / keys_.unitsPerMetre() / tickRate_;
    m.s.phase = Idle;
    m.firstCorner = corner(e.value("target"));
    if (m.firstCorner < 0) {
        keys_.warn(e, e.has("target") ? "target '" + e.value("target") + "' names no path_corner; the train stays"
                                      : "has no 'target' path_corner; the train stays");
        return;
    }
    // The path must go on from every corner (else Quake's "train_next: no next target").
    std::vector<int> seen;
    for (int c = m.firstCorner; c >= 0 && std::find(seen.begin(), seen.end(), c) == seen.end();) {
        seen.push_back(c);
        const map::LevelEntity& ce = level_.entities[static_cast<std::size_t>(c)];
        const int next = corner(ce.value("target"));
        if (next < 0) keys_.warn(ce, "path of the train at line " + std::to_string(e.pos.line) + " ends here (no next path_corner)");
        c = next;
    }
    m.s.offset = cornerOffset(m, m.firstCorner);
    m.s.step = m.firstCorner;
    if (m.targetname.empty()) {
        m.s.phase = Waiting;
        m.s.timer = std::max(1L, std::lround(kTrainCornerPause * tickRate_));
        m.s.cooldown = 1;  // started
    }
}

int Movers::corner(const std::string& name) const {
    if (name.empty()) return -1;
    for (std::size_t i = 0; i < level_.entities.size(); ++i)
        if (level_.entities[i].classname == "path_corner" && level_.entities[i].value("targetname") == name) return static_cast<int>(i);
    return -1;
}

Vec3 Movers::cornerOffset(const Mover& m, int c) const {
    // Quake's mins (least x, y, z) is this world's (min x, min y, max z): world z = -Quake y.
    const Vec3 mins{m.bounds.min.x, m.bounds.min.y, m.bounds.max.z};
    return level_.entities[static_cast<std::size_t>(c)].origin - mins;
}

// LinkDoors: func_doors whose boxes touch move as one; the group's first door is its master and
// owns the trigger field (none when any door of the group is targeted or shootable).
void Movers::linkDoors() {
    const int n = static_cast<int>(movers_.size());
    std::vector<int> parent(static_cast<std::size_t>(n));
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int i) {
        while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)];
        return i;
    };
    auto linkable = [&](const Mover& m) {
        return m.kind == MoverKind::Door && !(keys_.spawnflags(level_.entities[static_cast<std::size_t>(m.entity)]) & kDoorDontLink);
    };
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            if (linkable(movers_[i]) && linkable(movers_[j]) && overlaps(movers_[i].bounds, movers_[j].bounds, kTouchSlack)) {
                const int a = root(i), b = root(j);
                if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
            }
    for (int i = 0; i < n; ++i) {
        if (movers_[i].kind != MoverKind::Door) continue;
        movers_[i].master = root(i);
        movers_[movers_[i].master].group.push_back(i);
    }
    for (int i = 0; i < n; ++i) {
        Mover& m = movers_[i];
        if (m.kind != MoverKind::Door || m.master != i) continue;
        map::Aabb box;
        bool quiet = true;
        for (int d : m.group) {
            box.extend(movers_[d].bounds.min);
            box.extend(movers_[d].bounds.max);
            quiet &= movers_[d].targetname.empty() && !movers_[d].shootable && movers_[d].keys == 0;
        }
        const double upm = keys_.unitsPerMetre();
        m.field = quiet;
        m.fieldBox = grown(box, Vec3{kDoorFieldXY, kDoorFieldZ, kDoorFieldXY} / upm);
    }
}

int Movers::find(int entity) const {
    for (std::size_t i = 0; i < movers_.size(); ++i)
        if (movers_[i].entity == entity) return static_cast<int>(i);
    return -1;
}

void Movers::use(const std::string& targetname, std::vector<int>& fired) {
    if (targetname.empty()) return;
    std::vector<int> mastersFired;  // a group opens once however many of its doors are named
    for (std::size_t i = 0; i < movers_.size(); ++i) {
        if (movers_[i].targetname != targetname) continue;
        if (movers_[i].kind == MoverKind::Door) {
            if (std::find(mastersFired.begin(), mastersFired.end(), movers_[i].master) != mastersFired.end()) continue;
            mastersFired.push_back(movers_[i].master);
        }
        useMover(static_cast<int>(i), fired);
    }
}

void Movers::shot(const Vec3& point, std::vector<int>& fired) {
    map::Aabb p;
    p.extend(point);
    for (std::size_t i = 0; i < movers_.size(); ++i) {
        const Mover& m = movers_[i];
        if (m.shootable && overlaps(moved(m.bounds, m.s.offset), p, kShotSlack)) useMover(static_cast<int>(i), fired);
    }
}

void Movers::useMover(int i, std::vector<int>& fired) {
    Mover& m = movers_[i];
    switch (m.kind) {
    case MoverKind::Door: doorFire(m.master, fired); break;
    case MoverKind::Button: buttonFire(i); break;
    case MoverKind::SecretDoor: secretUse(i, fired); break;
    case MoverKind::Plat:  // plat_use: a targeted plat leaves the top once, then works as any plat
        if (m.s.phase == Up && !m.s.moving && m.s.step == 0) {
            m.s.step = 1;
            m.s.phase = Down;
            moveTo(i, m.pos2);
        }
        break;
    case MoverKind::Train:  // train_use: starts a train that waited for it
        if (m.s.cooldown == 0 && m.firstCorner >= 0) {
            m.s.cooldown = 1;
            trainNext(i);
        }
        break;
    }
}

// door_fire: a toggle door open or opening closes; otherwise every door of the group opens.
void Movers::doorFire(int master, std::vector<int>& fired) {
    const Mover& m = movers_[master];
    if (m.toggle && (m.s.phase == Up || m.s.phase == Top)) {
        for (int d : m.group) doorGoDown(d);
        return;
    }
    for (int d : m.group) doorGoUp(d, fired);
}

void Movers::doorGoUp(int i, std::vector<int>& fired) {
    Mover& m = movers_[i];
    if (m.s.phase == Up) return;
    if (m.s.phase == Top) {  // already open: wait again from now
        m.s.timer = m.wait > 0 && !m.toggle ? m.wait : 0;
        return;
    }
    m.s.phase = Up;
    moveTo(i, m.pos2);
    fired.push_back(m.entity);  // SUB_UseTargets
}

void Movers::doorGoDown(int i) {
    movers_[i].s.phase = Down;
    moveTo(i, movers_[i].pos1);
}

void Movers::buttonFire(int i) {
    Mover& m = movers_[i];
    if (m.s.phase == Up || m.s.phase == Top) return;
    m.s.phase = Up;
    moveTo(i, m.pos2);
}

void Movers::secretUse(int i, std::vector<int>& fired) {
    Mover& m = movers_[i];
    if (m.s.step != 0) return;  // still moving around
    fired.push_back(m.entity);
    m.s.step = 1;
    moveTo(i, m.dest1);
}

void Movers::trainNext(int i) {
    Mover& m = movers_[i];
    const int next = corner(level_.entities[static_cast<std::size_t>(m.s.step)].value("target"));
    if (next < 0) {  // the path ends (warned at load): stop here
        m.s.phase = Idle;
        return;
    }
    m.s.step = next;
    m.s.phase = Moving;
    moveTo(i, cornerOffset(m, next));
}

void Movers::moveTo(int i, const Vec3& dest) {
    movers_[i].s.dest = dest;
    movers_[i].s.moving = true;
}

// What each QuakeC move's callback does (door_hit_top, button_wait, plat_hit_top, fd_secret_moveN, train_wait).
void Movers::arrived(int i, std::vector<int>& fired) {
    Mover& m = movers_[i];
    State& s = m.s;
    switch (m.kind) {
    case MoverKind::Door:
        if (s.phase == Up) {
            s.phase = Top;
            s.timer = m.wait > 0 && !m.toggle ? m.wait : 0;
        } else {
            s.phase = Bottom;
        }
        break;
    case MoverKind::Button:
        if (s.phase == Up) {
            s.phase = Top;
            s.timer = m.wait > 0 ? m.wait : 0;
            fired.push_back(m.entity);
        } else {
            s.phase = Bottom;
        }
        break;
    case MoverKind::Plat:
        if (s.phase == Up) {
            s.phase = Top;
            s.timer = m.wait;
        } else {
            s.phase = Bottom;
        }
        break;
    case MoverKind::SecretDoor: {
        const long pause = std::lround(kSecretPause * tickRate_);
        if (s.step == 1 || s.step == 5) s.timer = pause;
        if (s.step == 3) s.timer = m.openOnce || m.wait <= 0 ? 0 : m.wait;
        s.step = s.step == 7 ? 0 : s.step + 1;
        break;
    }
    case MoverKind::Train: {
        const double wait = keys_.number(level_.entities[static_cast<std::size_t>(s.step)], "wait", 0);
        if (wait < 0) {
            s.phase = Idle;  // never goes on (Quake's think time in the past)
        } else {
            s.phase = Waiting;
            s.timer = std::max(1L, std::lround((wait > 0 ? wait : kTrainCornerPause) * tickRate_));
        }
        break;
    }
    }
}

// A wait ran out.
void Movers::think(int i, std::vector<int>& fired) {
    Mover& m = movers_[i];
    switch (m.kind) {
    case MoverKind::Door: doorGoDown(i); break;
    case MoverKind::Button:
        m.s.phase = Down;
        moveTo(i, m.pos1);
        break;
    case MoverKind::Plat:
        m.s.phase = Down;
        moveTo(i, m.pos2);
        break;
    case MoverKind::SecretDoor:
        if (m.s.step == 2) moveTo(i, m.dest2), m.s.step = 3;
        else if (m.s.step == 4) moveTo(i, m.dest1), m.s.step = 5;
        else if (m.s.step == 6) moveTo(i, Vec3{}), m.s.step = 7;
        break;
    case MoverKind::Train: trainNext(i); break;
    }
    (void)fired;
}

// door_blocked goes back (unless it never returns), plat_crush too; buttons, trains and secret
// doors just wait (Quake's pusher does not move that frame).
void Movers::blocked(int i, std::vector<int>& fired) {
    Mover& m = movers_[i];
    if (m.kind == MoverKind::Door && m.wait >= 0) {
        if (m.s.phase == Down) doorGoUp(i, fired);
        else doorGoDown(i);
    } else if (m.kind == MoverKind::Plat) {
        if (m.s.phase == Up) m.s.phase = Down, moveTo(i, m.pos2);
        else if (m.s.phase == Down) m.s.phase = Up, moveTo(i, m.pos1);
    }
}

// SV_PushMove for the one player: a rider (standing on the mover) or a player the mover would
// overlap moves with it; if that leaves the player inside something, nothing moves.
bool Movers::push(int i, const Vec3& to, PlayerState& player, const PlayerController& controller) {
    Mover& m = movers_[i];
    const Vec3 from = m.s.offset;
    const int self = moverUserIndex(i);
    const bool rider = controller.standingOn(player) == self;
    physics_.setKinematicOffset(m.body, to);
    if (!rider && controller.penetration(player, self) <= 0) return true;
    PlayerState carried = player;
    carried.feet += to - from;
    if (controller.penetration(carried, PlayerController::kAnyBody) > kCrushDepth) {
        physics_.setKinematicOffset(m.body, from);
        return false;
    }
    player = carried;
    return true;
}

int Movers::keysNeeded(int i) const { return movers_[static_cast<std::size_t>(movers_[static_cast<std::size_t>(i)].master)].keys; }

void Movers::unlock(int master, std::vector<int>& fired) {
    for (int d : movers_[static_cast<std::size_t>(master)].group) movers_[static_cast<std::size_t>(d)].keys = 0;
    doorFire(master, fired);
}

void Movers::step(PlayerState& player, const PlayerController& controller, std::vector<int>& fired) {
    keyDoorsTouched_.clear();
    const map::Aabb body = playerBox(player, controller.tuning().radius);
    for (std::size_t k = 0; k < movers_.size(); ++k) {
        const int i = static_cast<int>(k);
        Mover& m = movers_[k];
        if (m.s.cooldown > 0 && m.kind == MoverKind::Door) --m.s.cooldown;
        if (m.kind == MoverKind::Button && !m.shootable && overlaps(moved(m.bounds, m.s.offset), body, kTouchReach)) buttonFire(i);
        if (m.kind == MoverKind::Door && keysNeeded(i) && m.s.cooldown == 0 && overlaps(moved(m.bounds, m.s.offset), body, kTouchReach)) {
            m.s.cooldown = std::lround(kKeyDoorRepeat * tickRate_);  // door_touch's attack_finished
            keyDoorsTouched_.push_back(m.master);
        }
        if (m.kind == MoverKind::Door && m.field && m.s.cooldown == 0 && overlaps(m.fieldBox, body)) {
            m.s.cooldown = std::lround(kDoorFieldRepeat * tickRate_);  // door_trigger_touch's attack_finished
            doorFire(i, fired);
        }
        if (m.kind == MoverKind::Plat && overlaps(m.fieldBox, body)) {  // plat_center_touch
            if (m.s.phase == Bottom) m.s.phase = Up, moveTo(i, m.pos1);
            else if (m.s.phase == Top) m.s.timer = std::max(m.s.timer, std::lround(kPlatStayOnTop * tickRate_));
        }
    }
    for (std::size_t k = 0; k < movers_.size(); ++k) {
        const int i = static_cast<int>(k);
        State& s = movers_[k].s;
        const Vec3 before = s.offset;
        if (s.moving) {
            const Vec3 left = s.dest - s.offset;
            const double distance = length(left);
            const bool arrives = distance <= movers_[k].speed;
            const Vec3 to = arrives ? s.dest : s.offset + left * (movers_[k].speed / distance);
            if (!push(i, to, player, controller)) {
                blocked(i, fired);
            } else {
                s.offset = to;
                if (arrives) {
                    s.moving = false;
                    arrived(i, fired);
                }
            }
        }
        s.velocity = (s.offset - before) * tickRate_;
        if (s.timer > 0 && --s.timer == 0) think(i, fired);
    }
}

void Movers::hash(StateHasher& h) const {
    for (const Mover& m : movers_) {
        const State& s = m.s;
        for (double v : {s.offset.x, s.offset.y, s.offset.z, s.velocity.x, s.velocity.y, s.velocity.z, s.dest.x, s.dest.y, s.dest.z})
            h.add(v);
        h.add(static_cast<std::int32_t>(s.phase));
        h.add(static_cast<std::int32_t>(s.step));
        h.add(static_cast<std::uint64_t>(s.timer));
        h.add(static_cast<std::uint64_t>(s.cooldown));
        h.add(s.moving);
        if (m.keys) h.add(static_cast<std::int32_t>(m.keys));  // only key doors: other levels hash as before
    }
}

}  // namespace obscura::sim
