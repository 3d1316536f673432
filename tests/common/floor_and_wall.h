// The scene the ray-traced AO tests share: a 40 x 40 m floor at y = 0 and a 10 m wall standing on
// it along z = 0, facing +z.
#pragma once

#include "core/triangle_mesh.h"

#include <vector>

namespace obscura::testing_support {

inline std::vector<TriangleMesh> floorAndWall() {
    TriangleMesh floor;
    floor.vertices = {{-20, 0, -20}, {20, 0, -20}, {20, 0, 20}, {-20, 0, 20}};
    floor.indices = {0, 2, 1, 0, 3, 2};
    TriangleMesh wall;
    wall.vertices = {{-20, 0, 0}, {20, 0, 0}, {20, 10, 0}, {-20, 10, 0}};
    wall.indices = {0, 1, 2, 0, 2, 3};
    return {floor, wall};
}

}  // namespace obscura::testing_support
