// `--sign-mode meshuggah` (meshuggah.h), its plain-C++ half: the rays a sign casts through its
// coarse 8-bit mask (no OGRE: tests/signs/meshuggah_rays_test.cpp reads them).
#pragma once

#include "signs/sign_light.h"

#include <cstddef>
#include <vector>

namespace obscura::signs {

// The rays a sign casts, at most (the grid coarsens until this many or fewer pass).
constexpr std::size_t kMaxRays = 2048;
// The rays start this far in front of the plate (its front face is the plane): no fight with it.
constexpr double kStartOffset = 0.002;

// One ray of a sign's mask (plain data: the tests and the README's cost read it).
struct MeshuggahRay {
    Vec3 start, direction;  // on the plate's plane, world; unit, from the lamp
    double length = 0;      // metres from the plate to the range
    unsigned char coverage = 0;  // the 8-bit mask's value, 1..255
};
// The rays of `sign` through its coarse 8-bit mask (with `holes`), and the grid's spacing (metres):
// a texel every letterHeight / 32 (times 1.25 until at most kMaxRays pass), centred on the plate;
// coverage = clamp(0.5 + d / spacing, 0, 1) x the cone's smoothstep, quantised to 0..255, d the
// open distance (mask, holes) closed at the plate's edge; a ray per texel of coverage > 0, from the
// lamp's centre through the texel's centre, starting kStartOffset in front of the plane, ending at
// the range (|start - lamp| + length = range).
std::vector<MeshuggahRay> meshuggahRays(const SignSpec& sign, const SignMask& mask, const std::vector<Hole>& holes,
                                        double& spacing);

}  // namespace obscura::signs
