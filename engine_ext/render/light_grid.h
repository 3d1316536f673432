// Every map light, and which lights reach each cell of a world-space grid, packed into one float
// texture that level.frag reads per pixel (plain C++, no OGRE; LevelGeometry uploads it). A pixel
// loops over the lights of its own cell, however many: no light that reaches a surface is dropped,
// and props and models drawn with the level's program are lit by the same lights.
//
// Texture layout (RGBA32F, kLightGridWidth texels a row, addresses row-major):
//   from 0:           kLightTexels texels a light: (position, reach) (colour x value/200, formula
//                     + kSpotFlag for a spotlight) (map units a metre x wait, gate / strength,
//                     _anglescale, _falloff_exponent) (spot direction, cos of half the soft cone)
//                     (cos of half the cone, 0, 0, 0): the last two read for spotlights only
//   from headerBase:  one texel a cell, x fastest: (first index, count, 0, 0)
//   from indexBase:   light numbers, one a texel (r)
#pragma once

#include "map/level.h"

#include <cstddef>
#include <vector>

namespace obscura::render {

constexpr int kLightGridWidth = 2048;  // texels a row (a power of two: level.frag shifts); GL 3.3 GPUs take 8192 at least
constexpr int kLightTexels = 5;
constexpr int kSpotFlag = 8;  // added to a spotlight's formula (LEVEL_LIGHT_SPOT_FLAG)
// The grid has at most this many cells (a 4 MiB header at 16 bytes a cell): cells grow on large
// levels; e3m4's are 2.2 m (94 x 34 x 74, at most 15 lights a cell). Below 1 m a cell buys nothing
// (lights reach metres).
constexpr std::size_t kMaxLightGridCells = std::size_t(1) << 18;
constexpr double kMinLightGridCell = 1.0;

struct LightGrid {
    Vec3 origin;             // the grid's low corner, metres
    double cell = 1;         // cell edge, metres
    int nx = 1, ny = 1, nz = 1;
    int headerBase = 0, indexBase = 0;
    std::size_t indices = 0;  // light numbers over all cells
    std::size_t mostInACell = 0;
    std::vector<float> texels;  // RGBA, kLightGridWidth a row, whole rows
    int rows() const { return static_cast<int>(texels.size() / 4 / kLightGridWidth); }
    // The lights (their numbers in Level::lights) listed for the cell holding `p`.
    std::vector<int> lightsAt(const Vec3& p) const;
};

LightGrid buildLightGrid(const map::Level& level);

}  // namespace obscura::render
