// What the game prints on stderr when it loads a level (plain C++, no OGRE): each map warning as
// `file:line: text`, bounded, and one summary line with the load's times, its counts and the
// entity classes it did not know, counted by name.
#pragma once

#include "map/level.h"

#include <cstddef>
#include <string>
#include <vector>

namespace obscura::map {

struct LoadTimes {
    double parseMs = 0;    // reading and parsing the .map
    double compileMs = 0;  // brushes to polygons, entities to the Level
    double sessionMs = 0;  // the simulation's colliders, the smoke's voxels, the decals
    double sceneMs = 0;    // the renderer's scene (meshes, materials, lights)
};

// A level with thousands of bad brushes must not bury the terminal: 20 lines show the pattern,
// the rest is counted (and every warning still goes to the log).
constexpr std::size_t kMaxWarningLines = 20;
// Unknown classes named on the summary line before the rest is counted (e3m4 has 35: all shown).
constexpr std::size_t kMaxUnknownNames = 40;

// The warnings as they are (each already `file:line: text`), at most maxLines of them, then
// "obscura: ... and N more warnings (see the log)".
std::vector<std::string> warningLines(const std::vector<std::string>& warnings, std::size_t maxLines = kMaxWarningLines);

// "obscura: loaded FILE: parse 12.3 ms, compile 4.5 ms, session 6.7 ms, scene 89.0 ms; 3441 brushes,
// 1301 entities, 296 lights, 0 models; 0 warnings; unknown classes: monster_demon1 ×24, item_spikes ×20"
// (most frequent first, then by name; "unknown classes: none" when all are known).
std::string summaryLine(const Level& level, std::size_t warningCount, const LoadTimes& times);

}  // namespace obscura::map
