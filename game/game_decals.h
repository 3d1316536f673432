// The decals in the game (engine_ext/decals/decal_attach.h): the level's signs (decal_sign,
// engine_ext/decals/decal_sign.h: placed and baked at load, never recycled), a bullet hole at
// every rifle impact on the level or a prop (one on a prop follows it), a scorch mark under each
// grenade's detonation. The game owns them and advances them inside the tick (placed from the event and the
// count so far alone: the same in every replay); rendering reads list() one way and uploads it
// when version() moved.
#pragma once

#include "core/image.h"
#include "decals/decal_attach.h"
#include "map/level.h"
#include "settings.h"
#include "sim/simulation.h"

#include <cstdint>
#include <vector>

namespace obscura {

class GameDecals {
public:
    // The level's signs (a bad one skipped with a file:line line on stderr; searchDirs as
    // Session::modelSearchDirs); the ring's cap from settings.decals; settings.debugDecals holes
    // scattered by rays from the start eye (the cost bench).
    GameDecals(const Settings& settings, const map::Level& level, const std::vector<std::string>& searchDirs,
               const sim::Simulation& sim);

    // After each simulation tick: new holes and scorch marks from its events, then the decals on
    // props follow the props' poses.
    void onTick(const std::vector<sim::SimEvent>& events, const sim::Simulation& sim);

    const decals::DecalSet& set() const { return set_; }
    const std::vector<decals::Decal>& list() const { return set_.list(); }
    std::uint64_t version() const { return set_.version(); }
    // The signs' atlas tiles (DECAL_TILE * n x DECAL_TILE), after the build's DECAL_TILES.
    const Image& signTiles() const { return signTiles_; }

private:
    decals::DecalSet set_;
    Image signTiles_;
};

// The bodies' poses as the decals read them (index = dynamic body index).
std::vector<decals::BodyFrame> bodyFrames(const sim::Simulation& sim);

}  // namespace obscura
