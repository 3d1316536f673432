// What combat looks like: the targets (a bullseye board on a post that falls back when shot and
// rises again), the muzzle flash and impact sparks (additive billboards), all driven one way from
// the simulation's state and events. Effects advance per simulation tick (lifetimes in seconds,
// tick_durations.h), with their own seeded RNG, so replays capture the same pixels every run.
#pragma once

#include "core/rng.h"
#include "core/vec3.h"
#include "sim/sim_events.h"
#include "sim/simulation.h"
#include "tick_durations.h"

#include <vector>

namespace Ogre {
class BillboardSet;
class Entity;
class SceneManager;
class SceneNode;
}  // namespace Ogre

namespace obscura {
namespace render { class LevelMaterials; }

class CombatView {
public:
    // Effects age by ticks of `durations.tickSeconds`; their lifetimes are set in seconds.
    CombatView(Ogre::SceneManager& scene, render::LevelMaterials& materials, Ogre::SceneNode& cameraNode,
               const TickDurations& durations);
    ~CombatView();
    CombatView(const CombatView&) = delete;
    CombatView& operator=(const CombatView&) = delete;

    // Once per simulation tick, after it: spawns effects for its events and ages the old ones.
    void onTick(const std::vector<sim::SimEvent>& events);
    // Once per rendered frame: target boards follow the simulation.
    void update(const std::vector<sim::TargetState>& targets);

private:
    struct Spark {
        Vec3 position, velocity;
        int ticksLeft = 0, lifetime = 1;
    };
    struct TargetNodes {
        Ogre::SceneNode* base = nullptr;
        Ogre::SceneNode* pivot = nullptr;
        Ogre::Entity* board = nullptr;
        Ogre::Entity* post = nullptr;
    };
    void rebuildBillboards();

    Ogre::SceneManager& scene_;
    TickDurations durations_;
    render::LevelMaterials& materials_;
    Ogre::SceneNode* flashNode_ = nullptr;  // at the muzzle, a child of the camera
    Ogre::BillboardSet* flash_ = nullptr;
    Ogre::BillboardSet* sparks_ = nullptr;
    std::vector<Spark> live_;
    std::vector<TargetNodes> targets_;
    int flashTicks_ = 0;
    Rng rng_{0x5eed5a4c};  // effects only: never the simulation's
};

}  // namespace obscura
