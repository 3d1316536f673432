// The frame's knobs (see core/knob.h).
#pragma once

#include "core/knob.h"

namespace obscura::frame {

// Multiplies the HDR light before the tone map. 1.6: with the exponential tone map, a mid-grey wall
// under sky light lands near sRGB 0.5 and a sunlit one near 0.8.
inline constexpr Knob kExposure{"exposure", 1.6, 0.05, 20.0};

}  // namespace obscura::frame
