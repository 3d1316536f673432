// What liquids look like from the camera: the per-frame state of the ObscuraLiquid shared
// parameters (media/frame/frame.program) — the simulation time the surfaces warp by, and the
// medium (tint, fog) of the liquid the camera is in, which the output pass and the liquid surfaces
// apply (shaders/frame/output.frag, shaders/level/liquid.frag). The game decides where the camera
// is (map::LiquidQuery, plain C++) and pushes it here once a frame.
#pragma once

#include "core/vec3.h"
#include "map/level.h"

namespace obscura::render {

struct LiquidMedium {
    Vec3 tint{1, 1, 1};  // multiplies the light seen through it
    Vec3 fog;            // linear HDR colour the distance fades to
    double density = 0;  // per metre; 0: clear air
};

// The medium of each liquid (None: air).
LiquidMedium liquidMedium(map::LiquidKind kind);

// Sets the shared parameters for this frame. Throws if media/frame/frame.program lacks them.
void setLiquidView(double simSeconds, map::LiquidKind cameraIn);

}  // namespace obscura::render
