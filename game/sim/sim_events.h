// What happened during a simulation tick, for the game to turn into sound, effects and the HUD
// (one way: nothing here is read back by the simulation). Cleared at the start of every tick.
#pragma once

#include "core/vec3.h"

namespace obscura::sim {

enum class SimEventType {
    Shot,             // position = muzzle (the eye), direction = the ray after spread
    Impact,           // position = hit point, normal = surface normal, surface = what was hit (decals)
    TargetHit,        // id = target index
    TargetDown,       // id = target index
    TargetUp,         // id = target index (raised again after its reset time)
    PropHit,          // id = dynamic body index
    GrenadeThrow,     // position = release point, strength = speed m/s
    GrenadeBounce,    // position, strength = change of speed m/s
    GrenadeDetonate,  // position = where it lies: the smoke is released here
    Footstep,         // position = feet, id = 0..3 (alternating variations)
    Jump,
    Land,             // strength = fall speed m/s
    ReloadStart,
    ReloadEnd,
    DryFire,          // trigger pulled on an empty rifle with nothing to reload
    Teleport,         // position = the player's new feet, id = the trigger_teleport's entity (views do not interpolate across it)
    Message,          // id = the entity whose `message` Quake centre-prints (it used its targets: SUB_UseTargets), or notice set
    ChangeLevel,      // id = the trigger_changelevel the player touched (its `map` is the next level)
};

enum class Surface { Level, Target, Prop, Grenade };

// What a Message without an entity says (sim/pickups.h: noticeText words it).
enum class Notice { None, NeedSilverKey, NeedGoldKey, GotSilverKey, GotGoldKey };

struct SimEvent {
    SimEventType type = SimEventType::Shot;
    Vec3 position;
    Vec3 normal;
    Vec3 direction;
    double strength = 1;
    int id = -1;
    Surface surface = Surface::Level;
    Notice notice = Notice::None;  // a Message's words when it is not an entity's `message`

    static SimEvent at(SimEventType type, const Vec3& position) {
        SimEvent e;
        e.type = type;
        e.position = position;
        return e;
    }
};

}  // namespace obscura::sim
