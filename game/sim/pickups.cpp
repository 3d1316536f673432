// See pickups.h. Follows id Software's items.qc (key_touch) and doors.qc (door_touch), read, not copied.
#include "sim/pickups.h"

#include <cstdlib>

namespace obscura::sim {

namespace {
// Quake's item box about the origin, map units.
constexpr double kItemHalfWidth = 16, kItemBelow = 24, kItemAbove = 32;

bool overlaps(const map::Aabb& a, const map::Aabb& b) {
    return a.min.x <= b.max.x && a.max.x >= b.min.x && a.min.y <= b.max.y && a.max.y >= b.min.y && a.min.z <= b.max.z &&
           a.max.z >= b.min.z;
}
}  // namespace

Pickups::Pickups(const map::Level& level) {
    const double m = 1.0 / level.unitsPerMetre;
    for (const map::LevelEntity& e : level.entities) {
        const int key = e.classname == "item_key1" ? kSilverKey : e.classname == "item_key2" ? kGoldKey : 0;
        if (!key || !e.hasOrigin) continue;
        Item it;
        it.key = key;
        it.box.extend(e.origin - Vec3{kItemHalfWidth, kItemBelow, kItemHalfWidth} * m);
        it.box.extend(e.origin + Vec3{kItemHalfWidth, kItemAbove, kItemHalfWidth} * m);
        items_.push_back(it);
    }
}

void Pickups::step(const PlayerState& p, double r, std::vector<SimEvent>& events) {
    map::Aabb body;
    body.extend(p.feet - Vec3{r, 0, r});
    body.extend(p.feet + Vec3{r, static_cast<double>(p.height), r});
    for (Item& it : items_) {
        if (it.taken || !overlaps(it.box, body)) continue;
        it.taken = true;
        held_ |= it.key;
        SimEvent ev = SimEvent::at(SimEventType::Message, p.feet);
        ev.notice = it.key == kGoldKey ? Notice::GotGoldKey : Notice::GotSilverKey;
        events.push_back(ev);
    }
}

void Pickups::hash(StateHasher& h) const {
    if (items_.empty()) return;  // a level without keys hashes as it did before keys existed
    h.add(static_cast<std::int32_t>(held_));
    for (const Item& it : items_) h.add(it.taken);
}

int worldtypeOf(const map::Level& level) {
    const map::LevelEntity* world = level.entities.empty() ? nullptr : &level.entities.front();
    return world ? std::atoi(world->value("worldtype", "0").c_str()) : 0;
}

std::string noticeText(Notice notice, int worldtype) {
    const char* key = worldtype == 2 ? "keycard" : worldtype == 1 ? "runekey" : "key";
    switch (notice) {
        case Notice::NeedSilverKey: return std::string("You need the silver ") + key;
        case Notice::NeedGoldKey: return std::string("You need the gold ") + key;
        case Notice::GotSilverKey: return std::string("You got the silver ") + key;
        case Notice::GotGoldKey: return std::string("You got the gold ") + key;
        case Notice::None: break;
    }
    return {};
}

}  // namespace obscura::sim
