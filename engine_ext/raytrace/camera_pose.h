// The game's pinhole camera as the ray-traced references (tools/aoref, tools/signref) take it:
// an eye, yaw and pitch (the game's `--start-pose "x y z yaw pitch"`, degrees) and a horizontal
// field of view.
#pragma once

#include "core/vec3.h"

#include <string>

namespace obscura {

struct CameraPose {
    Vec3 eye;
    double yaw = 0, pitch = 0;  // radians; the game's convention (yaw about +Y, 0 faces -Z)
    double fovX = 90;           // horizontal field of view, degrees
};

// "x y z yaw pitch" (metres, degrees) as the game's --start-pose takes it; false when it is not
// five finite numbers.
bool parsePose(const std::string& text, double fovXDegrees, CameraPose& pose);

// The unit view direction through the image point (px, py) of a width x height image, in pixels
// from the top-left corner (a pixel's centre is x + 0.5, y + 0.5).
Vec3 cameraRay(const CameraPose& pose, int width, int height, double px, double py);

}  // namespace obscura
