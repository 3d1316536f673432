// Trigger volumes and target firing, as Quake's triggers.qc and subs.qc do them: trigger_once
// (and trigger_secret, a once), trigger_multiple (`wait` 0.2 s), trigger_relay, trigger_counter
// (fires on its `count`th use, default 2), trigger_teleport (to the
// info_teleport_destination named by `target`), trigger_push (`angle`, `speed` x 10 u/s, as
// QuakeC's trigger_push_touch), trigger_hurt (`dmg`, default 5, at most once a second) and
// trigger_changelevel (a ChangeLevel event naming it: the game loads its `map`). A trigger is the box around its brushes (Quake tests the
// absmin/absmax boxes too) and fires when the player's box is in it. Firing an entity uses its
// `target` (every entity of that targetname: movers, triggers) and removes its `killtarget`
// triggers, after its `delay`. Everything that evolves is in the state hash.
#pragma once

#include "core/state_hash.h"
#include "core/vec3.h"
#include "map/level.h"
#include "sim/entity_keys.h"
#include "sim/movers.h"
#include "sim/physics_world.h"
#include "sim/player_controller.h"
#include "sim/sim_events.h"

#include <string>
#include <vector>

namespace obscura::sim {

class Triggers {
public:
    // Warns (through `keys`) about a `target` or `killtarget` that names nothing, a teleporter
    // with no destination, a trigger with no brushes.
    Triggers(const map::Level& level, double tickRate, const EntityKeys& keys);

    // One tick, after the player moved: touches fire, teleport and push the player (and push
    // grenades); delayed firings come due. Appends a Teleport event when the player was moved.
    void step(PlayerState& player, double playerRadius, PhysicsWorld& physics, Movers& movers, std::vector<SimEvent>& events);
    // SUB_UseTargets for each entity in `fired` (movers that fired during the tick), with delays.
    void fire(const std::vector<int>& fired, Movers& movers);
    // Quake's `use` of the triggers named `targetname`.
    void use(const std::string& targetname, std::vector<int>& fired);
    // A Message event for each entity with a `message` that used its targets since the last call,
    // in firing order (SUB_UseTargets centre-prints it to the player).
    void takeMessages(std::vector<SimEvent>& events);

    std::size_t count() const { return triggers_.size(); }
    bool removed(std::size_t i) const { return triggers_.at(i).removed; }
    int entityIndex(std::size_t i) const { return triggers_.at(i).entity; }

    void hash(StateHasher& h) const;

private:
    enum class Kind { Once, Multiple, Relay, Counter, Teleport, Push, Hurt, ChangeLevel };
    struct Trigger {
        Kind kind = Kind::Multiple;
        int entity = 0;
        map::Aabb box;
        bool touchable = true;  // has brushes, not NOTOUCH
        long wait = 0;          // ticks between firings (multiple); -1: once
        Vec3 facing;            // trigger_multiple with an angle: only entered facing this way
        bool directional = false;
        int destination = -1;   // teleport: entity index
        Vec3 push;              // push: the velocity it sets, m/s
        bool pushOnce = false;
        int damage = 0;         // hurt: health taken a touch (`dmg`)
        std::string targetname;
        // state
        long cooldown = 0;      // ticks until it may fire again (multi_wait); teleport: ticks it stays enabled
        int count = 0;          // counter: uses still needed
        bool removed = false;
    };
    struct Pending {
        long ticks;
        int entity;
    };

    void useTargets(int entity, Movers& movers);
    void useNow(int entity, Movers& movers, int depth);
    void multiTrigger(Trigger& t, std::vector<int>& fired);
    bool touching(const Trigger& t, const PlayerState& player, double radius) const;

    const map::Level& level_;
    const EntityKeys& keys_;
    double tickRate_;
    std::vector<Trigger> triggers_;
    std::vector<Pending> pending_;  // delayed firings, in the order they were made
    std::vector<int> messages_;     // entities whose message is due (drained every tick)
};

}  // namespace obscura::sim
