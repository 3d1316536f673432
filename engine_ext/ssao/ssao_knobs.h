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
// 32 (the seeds' 10-16 doubled): the horizon searches' error follows their steps a side, and at 32
// the combined default's small term (GTAO) is .070 occluded-region MAE on room_a against .100 at 16;
// its added frame time at 1280x720 quarter resolution is then still about a fifth of the
// full-resolution 32-sample hemisphere's (README.md, Cost). The kernel holds SSAO_MAX_SAMPLES.
inline constexpr Knob kSamples{"ssao-samples", 32, 1, SSAO_MAX_SAMPLES};

}  // namespace obscura::ssao
