// The irradiance a view should show, path-traced with Embree (plain C++): for each pixel's surface,
// the map's lights with their shadows, the sun (Lambert, its ray), the sky dome where it is seen,
// and `bounces` diffuse bounces (albedo as the bake's), with `samples` paths a pixel. Beside it,
// the model the frame used before the light bake (issue 32), for the error table: the sun with an
// exact shadow (kinder to it than its shadow map was), the lights unshadowed, the hemispheric
// ambient scaled by env_ambient. Units: the frame's linear irradiance.
#pragma once

#include "lightbake/light_bake.h"
#include "raytrace/camera_pose.h"

#include <vector>

namespace obscura::lightref {

struct Irradiance {
    int width = 0, height = 0;
    std::vector<float> rgb;     // top row first
    std::vector<char> surface;  // 1 where the pixel's ray meets a (non-sky) face
};

struct ReferenceSettings {
    int samples = 64;  // paths a pixel
    int bounces = 3;   // diffuse bounces after the first hit
    int threads = 0;
};

Irradiance pathTraced(const map::Level& level, const CameraPose& pose, int width, int height, const ReferenceSettings& s);
// The frame's model before the bake, at the same pixels (the surface mask is the reference's).
Irradiance beforeTheBake(const map::Level& level, const CameraPose& pose, int width, int height);

// RMSE of the pixels' luminance over the reference's surface pixels (the PFM's rows top first).
double rmse(const Irradiance& reference, const std::vector<float>& rgb);

}  // namespace obscura::lightref
