// Reading a point entity's values strictly, the way the painted signs (decals/decal_sign.cpp) and
// the back-lit signs (signs/sign_light.cpp) do: a value must be exactly the numbers asked for
// (locale-independent; the caller checks ranges), and every problem comes back as a reason for
// the caller's "file:line: <class> skipped: <why>". Plain C++. (The movers and triggers read keys
// the way QuakeC's atof does instead: game/sim/entity_keys.h.)
#pragma once

#include "core/vec3.h"
#include "map/level.h"

#include <cstddef>
#include <string>
#include <vector>

namespace obscura::map {

// The value's words, split at spaces, tabs and commas.
std::vector<std::string> valueWords(const std::string& s);
// Exactly `n` numbers ("nan" and "inf" parse: the caller checks finiteness).
bool valueNumbers(const std::string& text, std::size_t n, double* out);
// `s` in single quotes for a message, cut after 64 characters.
std::string quotedValue(const std::string& s);
// A `message` as Quake shows it: ED_NewString turns the two characters `\n` into a line break.
std::string messageText(const std::string& value);

// A Quake point (map units, x east, y north, z up) in the level's world: (x, z, -y) / units per
// metre, computed as the compiler computes entity origins (so a key holding a point lands exactly
// where an entity at that origin would).
Vec3 mapPointToWorld(const Vec3& quake, double unitsPerMetre);

// `origin`, compiled, checked against its raw text (a non-number may have been read as 0).
// Returns "" or the reason.
std::string readOrigin(const LevelEntity& e, Vec3& out);

// How a sign-like entity is turned: `mangle` ("pitch yaw roll", degrees, Quake's: pitch down
// positive) or else `angle` (the yaw, degrees CCW from east seen from above); neither faces east.
// facing: the way the entity faces (Quake's forward); right and up: the entity's own axes seen
// from in front, yaw alone giving the horizontal right and the world up, pitch tipping up with the
// facing, roll (radians in `roll`) turning right and up about the facing, counter-clockwise seen
// from in front. Orthonormal, facing = cross(right, up).
struct Orientation {
    Vec3 right{0, 0, -1}, up{0, 1, 0}, facing{1, 0, 0};
    double roll = 0;  // radians
};
std::string readOrientation(const LevelEntity& e, Orientation& out);

// An "r g b" colour key, 0..1 or 0..255 (Quake maps write either: any component over 1 means
// 0..255), into `out` as 0..1. Returns "" or the reason; `out` unchanged when the key is absent.
std::string readColour(const LevelEntity& e, const std::string& key, Vec3& out);

}  // namespace obscura::map
