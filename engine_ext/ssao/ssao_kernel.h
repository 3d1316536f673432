// SSAO sample kernels, plain C++ (seeded, deterministic):
//  - a random start: directions uniform on the unit hemisphere (z >= 0, tangent space, z = normal)
//    or sphere (Crytek-style depth-only SSAO);
//  - relaxation by energy minimisation (Malmer, "Screen-space ambient occlusion", 2008: ~100
//    iterations of mutual repulsion between the sample directions), which spreads the samples
//    evenly so fewer of them give less noise;
//  - radii then randomised, denser near the centre (occluders near the surface matter most).
// Quality measures used by the tests and the tools: the minimum pairwise angular distance and a
// spherical-cap discrepancy estimate.
#pragma once

#include "core/vec3.h"

#include <cstdint>
#include <vector>

namespace obscura::ssao {

enum class KernelShape { Hemisphere, Sphere };

// `count` unit directions, uniformly random.
std::vector<Vec3> randomDirections(int count, KernelShape shape, std::uint64_t seed);

// Repulsion relaxation of unit directions (kept on the unit hemisphere/sphere).
// 100 iterations: Malmer's figure, and where the minimum distance stops improving for 8-32 samples.
std::vector<Vec3> relaxDirections(std::vector<Vec3> dirs, KernelShape shape, int iterations = 100);

// Scales direction i by a radius in (0.1, 1]: r = lerp(0.1, 1, s^2) over an evenly spaced,
// shuffled s, so every kernel covers near and far without clumping.
std::vector<Vec3> randomiseRadii(std::vector<Vec3> dirs, std::uint64_t seed);

// A kernel: relaxed directions with randomised radii.
std::vector<Vec3> makeKernel(int count, KernelShape shape, std::uint64_t seed);

// What the AO shaders read for `samples` samples: a kernel relaxed for that count, zero-padded to
// `slots` entries (the shader's uniform array). Not the first `samples` of a bigger relaxed kernel:
// a prefix of an even set is about as uneven as a random one (16 of 32: cap discrepancy 0.235
// against 0.123 relaxed for 16).
std::vector<Vec3> kernelFor(int samples, int slots, KernelShape shape, std::uint64_t seed);

double minPairwiseDistance(const std::vector<Vec3>& dirs);  // between normalised directions
// Largest |fraction of directions inside a cap - the cap's share of the domain| over `caps`
// seeded random caps (angles 10..90 degrees). 0 is perfectly even.
double capDiscrepancy(const std::vector<Vec3>& dirs, KernelShape shape, int caps = 2000, std::uint64_t seed = 7);

}  // namespace obscura::ssao
