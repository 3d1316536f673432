// A tuned value with its range: one table per technique (ssao/ssao_knobs.h, frame/frame_knobs.h),
// read by the settings parser (defaults, range checks), the ImGui panel (slider ranges) and the
// passes (clamping), so a default or a limit is written once.
#pragma once

namespace obscura {

struct Knob {
    const char* name;  // the setting's name (--name, config key)
    double value;      // the default
    double min, max;   // the accepted range, inclusive
    double clamp(double v) const { return v < min ? min : v > max ? max : v; }
};

}  // namespace obscura
