// The lamps that light and are shadowed by the smoke, chosen on the smoke's worker
// (smoke_pipeline.h) after each step from the clouds' occupied boxes. Plain C++, no OGRE: what
// the renderer binds (smoke_render.cpp) and what the lamp maps are swept towards come from here.
#pragma once

#include <cstddef>
#include <vector>

#include "core/vec3.h"
#include "map/level.h"

namespace obscura::smoke {

// A point light that can light the smoke: world position, linear colour (as the level's surfaces
// get it), range in metres (the light reaches zero there: (1 - d / range)^2).
struct SmokeLamp {
    Vec3 position, colour;
    double range = 0;
};

// An axis-aligned box in world space: the part of a volume's grid that holds smoke.
struct SmokeBox {
    Vec3 min, size;
};

// Lamp map channels a volume has (RGBA), and how many of them the signs may take: SIGN_MAX_LIGHTS
// (2) signs are lit at a time (engine_ext/signs), so at least two channels stay for the level's.
constexpr std::size_t kShadowedLamps = 4, kShadowedSignLamps = 2;

struct LampChoice {
    // The level lamps whose range reaches a box, the brightest at its nearest point of a box
    // first, at most SMOKE_MAX_LIGHTS (smoke_shared.h).
    std::vector<SmokeLamp> bound;
    // The lamp maps' channels (at most kShadowedLamps): bound's first `shadowedLevelLamps`, then
    // the sign lamps that reach a box, the nearest first (at most kShadowedSignLamps).
    std::vector<Vec3> shadowed;
    std::size_t shadowedLevelLamps = 0;
};

// The level's point lights as the smoke sees them (spotlights are left out: the march has no
// cone), sorted by position so a tie in the choice never depends on the level's entity order.
std::vector<SmokeLamp> levelLamps(const map::Level& level);

LampChoice chooseLamps(const std::vector<SmokeBox>& boxes, const std::vector<SmokeLamp>& level,
                       const std::vector<SmokeLamp>& signs);

}  // namespace obscura::smoke
