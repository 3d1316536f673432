// See camera_pose.h.
#include "raytrace/camera_pose.h"

#include <cmath>
#include <sstream>

namespace obscura {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

bool parsePose(const std::string& text, double fovXDegrees, CameraPose& pose) {
    std::istringstream is(text);
    double x, y, z, yaw, pitch;
    if (!(is >> x >> y >> z >> yaw >> pitch)) return false;
    std::string rest;
    if (is >> rest) return false;
    if (!std::isfinite(x + y + z + yaw + pitch)) return false;
    pose.eye = {x, y, z};
    pose.yaw = yaw * kPi / 180.0;
    pose.pitch = pitch * kPi / 180.0;
    pose.fovX = fovXDegrees;
    return true;
}

Vec3 cameraRay(const CameraPose& pose, int width, int height, double px, double py) {
    const double tanX = std::tan(pose.fovX * kPi / 360.0), tanY = tanX * height / width;
    const double cy = std::cos(pose.yaw), sy = std::sin(pose.yaw), cp = std::cos(pose.pitch), sp = std::sin(pose.pitch);
    const Vec3 c{(2.0 * px / width - 1.0) * tanX, (1.0 - 2.0 * py / height) * tanY, -1.0};
    // camera -> world: pitch about X, then yaw about Y
    const Vec3 q{c.x, c.y * cp - c.z * sp, c.y * sp + c.z * cp};
    return normalize(Vec3{q.x * cy + q.z * sy, q.y, -q.x * sy + q.z * cy});
}

}  // namespace obscura
