// The AO knobs: defaults and ranges in one table (see core/knob.h), each with its reason.
#pragma once

#include "core/knob.h"
#include "ssao/ssao_shared.h"

namespace obscura::ssao {

// Metres: about a hand's span, where contact shadows read; past 5 m the screen holds too little
// of what occludes.
inline constexpr Knob kRadius{"ssao-radius", 0.6, 0.05, 5.0};
// Measured against the ray-traced reference (README.md): 2 beats 1 on most views.
inline constexpr Knob kIntensity{"ssao-intensity", 2.0, 0.0, 4.0};
// Metres: the combined mode's large scale (the height map's rays, from --ssao-radius out to this).
// 2: the error table's large-scale truth, the reach at which a room, a corridor or a 12 m wall
// darkens what is near it; README.md has the measurements.
inline constexpr Knob kLargeRadius{"ssao-large-radius", 2.0, 0.5, 10.0};
// 16: the seeds' 10-16, at a quarter of the resolution; the kernel holds SSAO_MAX_SAMPLES.
inline constexpr Knob kSamples{"ssao-samples", 16, 1, SSAO_MAX_SAMPLES};

}  // namespace obscura::ssao
