// Quake's keys (items.qc): item_key1 (the silver key) and item_key2 (the gold key) are picked up
// when the player's box touches theirs (Quake's item box, -16 -16 -24 to 16 16 32 about the
// origin), once each; a key door (func_door spawnflags 16 silver, 8 gold) needs the key and uses
// it up (doors.qc's door_touch). A Message event with its Notice says so, in the words Quake uses
// for the level's `worldtype` (0 key, 1 runekey, 2 keycard). The keys held and the keys taken are
// in the state hash when the level has any key.
#pragma once

#include "core/state_hash.h"
#include "map/level.h"
#include "sim/player_controller.h"
#include "sim/sim_events.h"

#include <string>
#include <vector>

namespace obscura::sim {

constexpr int kSilverKey = 1, kGoldKey = 2;  // Pickups' bits (Quake's IT_KEY1, IT_KEY2)

class Pickups {
public:
    explicit Pickups(const map::Level& level);

    // The player's touches this tick: keys taken (a GotKey notice each).
    void step(const PlayerState& player, double playerRadius, std::vector<SimEvent>& events);
    bool holds(int keys) const { return (held_ & keys) == keys; }
    void use(int keys) { held_ &= ~keys; }
    int held() const { return held_; }

    void hash(StateHasher& h) const;

private:
    struct Item {
        int key = 0;
        map::Aabb box;
        bool taken = false;
    };
    std::vector<Item> items_;
    int held_ = 0;
};

// Quake's words for a notice in a level of `worldtype` (worldspawn's key: 0 medieval, 1 metal, 2 base).
std::string noticeText(Notice notice, int worldtype);
// The level's worldspawn `worldtype` (0 when absent).
int worldtypeOf(const map::Level& level);

}  // namespace obscura::sim
