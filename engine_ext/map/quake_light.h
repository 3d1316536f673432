// Quake's light falloff, in plain C++: what a light entity adds to a surface point, as irradiance
// (linear RGB, the G-buffer's direct light). shaders/level/level.frag evaluates the same formulas per
// pixel; tests/lighting compares the two.
//
// The formulas are ericw-tools' light.exe (docs/light.rst, "delay"): with x the distance in map
// units times `wait` (and worldspawn `_dist`) and S = 128 (Quake's LF_SCALE),
//   delay 0  value - x (to 0)       delay 1  value S / x        delay 2  value S^2 / x^2
//   delay 3  value                  delay 4  value, as a floor   delay 5  value S^2 / (x + S)^2
// `_falloff` (delay 0 only) replaces the reach with a distance of its own. The angle of incidence
// counts as (1 - anglescale) + anglescale cos (`_anglescale`, default 0.5); a spotlight's cone cuts
// to 0 outside half its angle, with a linear ramp in the cosine from `_softangle`.
#pragma once

#include "map/level.h"

#include <string>
#include <vector>

namespace obscura::map {

// One scale for every Quake light value in this project (lights, `_minlight`, `_sunlight`): a value
// of 200 is irradiance 1.0, so Quake's default light (300) is 1.5 beside the bulb. (Quake's
// overbright renderers show lightmap 128 as 1.0; 200 keeps the tone map and the arena as tuned.)
constexpr double kQuakeLightUnit = 200.0;
// Quake's LF_SCALE: the distance, in map units, at which an inverse light equals its value.
constexpr double kInverseLightScale = 128.0;
// Inverse-law lights never reach 0: they are cut where they add less than this much irradiance
// (about a quarter of an 8-bit step on a mid-grey wall after the tone map), and the gate is
// subtracted so the cut has no edge. 300 at delay 2 then reaches 49 m; at delay 1, 600 m.
constexpr double kLightGate = 0.01;
// Inverse-law distances below this many map units count as this (no infinity at the bulb).
constexpr double kMinInverseDistance = 16.0;
// ericw-tools' default spotlight cone (`angle`), degrees.
constexpr double kDefaultSpotCone = 40.0;

// The light's irradiance scale at distance `metres`, before colour, angle and cone: value/unit times
// the formula's fraction (so a linear light of value v gives v/200 at 0 and 0 at its reach).
// LocalMinimum lights return their constant floor (the caller takes the max, not the sum).
double lightAtDistance(const LevelLight& light, double metres);

// The angle of incidence factor for `cosine` = dot(surface normal, direction to the light).
double angleFactor(const LevelLight& light, double cosine);

// The cone factor for `cosine` = dot(spot direction, direction from the light to the point).
double spotFactor(const LevelLight& light, double cosine);

// The irradiance (scalar, times the colour for RGB) at `point` with normal `normal`.
double lightAt(const LevelLight& light, const Vec3& point, const Vec3& normal);

// Metres at which the light stops adding anything (the cut): linear = where it reaches 0 (or
// `_falloff`); inverse laws = where it falls to kLightGate; none/local minimum = `levelSize`.
double lightReach(const LevelLight& light, double levelSize);

}  // namespace obscura::map
