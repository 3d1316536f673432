// An indexed triangle soup in world space (metres, Y up): misc_model colliders, and later the
// smoke voxeliser and the ray-traced AO reference.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace obscura {

struct TriangleMesh {
    std::vector<Vec3> vertices;
    std::vector<std::uint32_t> indices;  // three per triangle
};

}  // namespace obscura
