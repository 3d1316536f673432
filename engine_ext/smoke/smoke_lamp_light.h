// The level's lamps' light on the smoke, computed once per cell of a volume's grid on the smoke's
// worker (smoke_pipeline.cpp, after the lamp maps) instead of per sample per pixel in the march:
// the march read every bound lamp (up to SMOKE_MAX_LIGHTS) and its shadow at every sample, half of
// a cloud's cost on llvmpipe (engine_ext/smoke/README.md, "The lamps' light on the grid"). Plain
// C++, no OGRE.
//
// Per cell, from each bound lamp l at distance d with range r, colour c and transmittance T (the
// smoke's and its walls', from the lamp maps; 1 for the lamps not shadowed):
//   single scattering    a_l = c (1 - d / r)^2 T            (the march's phase g)
//   multiple scattering  b_l = c (1 - d / r)^2 kLampMultipleWeight sqrt(T)   (phase g / 2)
// Two RGBA texels a cell (shaders/smoke/smoke_march.glsl, smokeLampLightAt):
//   A = (sum of a_l + b_l, the single share of its luminance)
//   B = (the luminance-weighted mean of the unit directions to the lamps, 0)
// The march applies the phases about B's direction with g scaled by B's length (1: one lamp, or
// all lamps one way; towards 0 as they surround the cell and the phases average out). Exact for one
// lamp at a cell's centre; with several, their mean direction stands for them.
#pragma once

#include <cstddef>
#include <vector>

#include "smoke/smoke_grid.h"
#include "smoke/smoke_lamps.h"

namespace obscura::smoke {

// The multiple-scattering octave's weight beside the single-scattering term (Wrenninge et al. 2013,
// as the sun's second octave: the light that diffuses deeper into the cloud than it passes straight).
constexpr float kLampMultipleWeight = 0.5f;

// Texels a cell in lampLight's output: A then B, each RGBA.
constexpr std::size_t kLampLightTexels = 2;

// Fills `out` with 8 floats a cell: A for every cell (4 n floats, grid order), then B (4 n): zero
// outside `occupied` widened by a cell (trilinear reach) and where no lamp reaches. `lampT`: 4
// floats a cell (exportLampTransmittance; channel l < shadowedLevelLamps is lamp l's), or empty.
void lampLight(const GridInfo& grid, const SmokeBox& occupied, const std::vector<SmokeLamp>& lamps,
               std::size_t shadowedLevelLamps, const std::vector<float>& lampT, std::vector<float>& out);

}  // namespace obscura::smoke
