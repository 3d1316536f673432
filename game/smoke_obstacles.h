// What pushes a smoke grenade's cloud in the game, read from the simulation's state: the plain-C++
// link between sim/ (Bullet) and smoke/ (the solver's MovingObstacle), kept apart from the OGRE
// glue (app/game_smoke.*) so it is tested without a window.
#pragma once

#include <vector>

#include "sim/simulation.h"
#include "smoke/smoke_volume.h"

namespace obscura {

// The player (a box the size of the capsule), every prop (the axis-aligned box around it as it
// lies: the solver's boxes do not rotate) and every grenade (a sphere), with their velocities.
// Props at rest are obstacles too: smoke flows around a crate instead of through it. So is every
// mover's brush (its box where the mover is now): a closed door holds the smoke, an open one not.
std::vector<smoke::MovingObstacle> smokeObstacles(const sim::Simulation& sim);

}  // namespace obscura
