// The back-lit signs' knobs (see core/knob.h).
#pragma once

#include "core/knob.h"

namespace obscura::signs {

// The haze's scattering coefficient, per metre: the air of a closed dark room (dust, a little
// smoke) that shows the shafts with no grenade about. 0.03: the default lamp's beam shows as a
// clear shaft across a 12 m room at exposure 1.6 without veiling the room; its extinction (0.3 over
// 10 m, neglected: sign_march.glsl) is what limits the knob to 0.2.
inline constexpr Knob kHaze{"sign-haze", 0.03, 0.0, 0.2};

}  // namespace obscura::signs
