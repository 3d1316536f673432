// The back-lit signs in the game (engine_ext/signs/sign_light.h): the level's light_signs, read and
// their masks baked at load (a bad one skipped with its file:line on stderr), and the bullet holes
// the rifle punches through their plates: a shot whose ray crosses a plate before it hits anything
// else opens a disc there and goes on. Placed from the tick's events alone, so every replay makes
// the same holes; rendering reads holes() one way and uploads them when version() moved.
#pragma once

#include "map/level.h"
#include "signs/sign_light.h"
#include "sim/sim_events.h"

#include <cstdint>
#include <string>
#include <vector>

namespace obscura {

// A rifle round's hole in a sign's plate (metres): sheet metal tears about twice the calibre
// wide, and 2 cm is what still shows as a beam in the haze from across a room.
constexpr double kSignHoleRadius = 0.02;

class GameSigns {
public:
    GameSigns(const map::Level& level, const std::vector<std::string>& fontDirs);

    // After each simulation tick: holes from its shots.
    void onTick(const std::vector<sim::SimEvent>& events);

    const std::vector<signs::SignSpec>& specs() const { return specs_; }
    const std::vector<signs::SignMask>& masks() const { return masks_; }
    const std::vector<signs::SignHoles>& holes() const { return holes_; }
    std::uint64_t version() const { return version_; }

private:
    std::vector<signs::SignSpec> specs_;
    std::vector<signs::SignMask> masks_;
    std::vector<signs::SignHoles> holes_;
    std::uint64_t version_ = 0;
};

// Where a ray (origin, unit direction) crosses the plate of `sign` (`mask` gives its extent) from
// the front or the back within maxT: the distance, and the crossing in plate coordinates.
bool rayCrossesPlate(const signs::SignSpec& sign, const signs::SignMask& mask, const Vec3& origin, const Vec3& dir,
                     double maxT, double& t, double& x, double& y);

}  // namespace obscura
