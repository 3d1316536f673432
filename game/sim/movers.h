// Moving brushes, as Quake's QuakeC moves them (doors.qc, plats.qc, buttons.qc, the trains of
// plats.qc): func_door (with linked doors and the trigger field around them), func_door_secret,
// func_plat, func_button, func_train following path_corners. Each mover is one kinematic Bullet
// body (a convex hull per brush) translated from where the level built it; it moves at its speed
// each fixed tick, carries a player standing on it and pushes one in its way, and when that
// player would be crushed into something it does what Quake does (a door or plat goes back, the
// others wait). Waits are whole ticks. Everything that evolves is in the state hash.
// Plain C++ + Bullet; the game reads offsets and velocities (render nodes, smoke obstacles).
#pragma once

#include "core/state_hash.h"
#include "core/vec3.h"
#include "map/level.h"
#include "sim/entity_keys.h"
#include "sim/physics_world.h"
#include "sim/player_controller.h"

#include <string>
#include <vector>

namespace obscura::sim {

enum class MoverKind { Door, SecretDoor, Plat, Button, Train };

class Movers {
public:
    // Builds every mover entity of `level` (isMoverClass) that has brushes; bad keys, a door with no
    // brushes, a train with no path_corner are warnings (through `keys`), never errors. Throws
    // SimError only for a degenerate brush, as the static world does.
    Movers(const map::Level& level, PhysicsWorld& physics, double tickRate, const EntityKeys& keys);

    std::size_t count() const { return movers_.size(); }
    MoverKind kind(std::size_t i) const { return movers_.at(i).kind; }
    int entityIndex(std::size_t i) const { return movers_.at(i).entity; }
    // Translation from the pose the level was built in, metres, and this tick's velocity, m/s.
    const Vec3& offset(std::size_t i) const { return movers_.at(i).s.offset; }
    const Vec3& velocity(std::size_t i) const { return movers_.at(i).s.velocity; }
    // Its brushes' boxes as built (add offset() for where they are now).
    const std::vector<map::Aabb>& brushBounds(std::size_t i) const { return movers_.at(i).brushes; }
    // Where a door / button / plat would rest open (Quake's pos2), as an offset.
    const Vec3& openOffset(std::size_t i) const { return movers_.at(i).pos2; }
    // The mover of entity `entity`, or -1.
    int find(int entity) const;

    // Quake's `use` of every mover named `targetname` (a trigger, button or door fired it).
    // Entities whose own targets fire because of it are appended to `fired`.
    void use(const std::string& targetname, std::vector<int>& fired);
    // A shot hit `point` (an Impact): a shootable door (`health`), button (`health`) or secret door
    // there opens, as Quake's th_pain / th_die do.
    void shot(const Vec3& point, std::vector<int>& fired);
    // One tick: the player's touches (buttons, the doors' trigger fields, the plats' inside
    // triggers), then every mover's motion with the player carried or pushed.
    void step(PlayerState& player, const PlayerController& controller, std::vector<int>& fired);
    // Key doors (sim/pickups.h): the groups whose locked door the player touched this tick (at
    // most once in 2 s each), the keys a door's group still needs, and opening it with them.
    const std::vector<int>& keyDoorsTouched() const { return keyDoorsTouched_; }
    int keysNeeded(int i) const;
    void unlock(int master, std::vector<int>& fired);

    void hash(StateHasher& h) const;

private:
    enum Phase { Bottom, Up, Top, Down, Idle, Moving, Waiting };
    struct State {  // everything that evolves
        Vec3 offset, velocity;
        Vec3 dest;             // where the current move ends
        int phase = Bottom;
        int step = 0;          // secret door: 0..6 of its sequence; train: the corner it heads for (entity)
        long timer = 0;        // ticks left of a wait; 0: none
        long cooldown = 0;     // door field / plat trigger: ticks until it may fire again
        bool moving = false;
    };
    struct Mover {
        MoverKind kind = MoverKind::Door;
        int entity = 0, body = 0;
        std::vector<map::Aabb> brushes;
        map::Aabb bounds;          // all brushes, as built
        std::string targetname;
        Vec3 pos1, pos2;           // offsets: door/button closed, open; plat top, bottom
        double speed = 0;          // metres per tick
        long wait = 0;             // ticks; negative: never comes back
        bool toggle = false, shootable = false;
        int keys = 0;              // door: kSilverKey | kGoldKey still needed (0 once unlocked)
        int master = -1;           // doors: the group's first door; others: itself
        std::vector<int> group;    // on the master: every door of the group (itself first)
        bool field = false;        // master door / plat: has a trigger volume
        map::Aabb fieldBox;
        // secret door
        Vec3 dest1, dest2;
        bool openOnce = false;
        // train
        int firstCorner = -1;
        State s;
    };

    void slideAlongAngle(Mover& m, const map::LevelEntity& e, double speed, double wait, double lip);
    void buildDoor(Mover& m, const map::LevelEntity& e);
    void buildButton(Mover& m, const map::LevelEntity& e);
    void buildPlat(Mover& m, const map::LevelEntity& e);
    void buildSecret(Mover& m, const map::LevelEntity& e);
    void buildTrain(Mover& m, const map::LevelEntity& e);
    void linkDoors();
    int corner(const std::string& targetname) const;  // entity index of the path_corner, or -1
    Vec3 cornerOffset(const Mover& m, int cornerEntity) const;

    void useMover(int i, std::vector<int>& fired);
    void doorFire(int master, std::vector<int>& fired);
    void doorGoUp(int i, std::vector<int>& fired);
    void doorGoDown(int i);
    void buttonFire(int i);
    void secretUse(int i, std::vector<int>& fired);
    void trainNext(int i);
    void moveTo(int i, const Vec3& dest);
    void arrived(int i, std::vector<int>& fired);
    void think(int i, std::vector<int>& fired);
    void blocked(int i, std::vector<int>& fired);
    bool push(int i, const Vec3& to, PlayerState& player, const PlayerController& controller);

    const map::Level& level_;
    PhysicsWorld& physics_;
    const EntityKeys& keys_;
    double tickRate_;
    std::vector<Mover> movers_;
    std::vector<int> keyDoorsTouched_;  // this tick's (not state: cleared every step)
};

}  // namespace obscura::sim
