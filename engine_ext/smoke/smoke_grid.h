// The smoke grid: geometry (origin, dimensions, cell size) and the cell classes the solver and the
// voxeliser share. Plain C++, no OGRE.
//
// Layout: one flat array per field, x fastest: index = i + nx * (j + ny * k). Cell (i, j, k)
// covers [origin + (i, j, k) * h, origin + (i + 1, j + 1, k + 1) * h]; its centre is at
// origin + (i + 0.5, j + 0.5, k + 0.5) * h. The outermost layer of cells (i, j or k equal to 0 or
// n - 1) is a ghost layer: never advected, either solid or open (pressure 0, density 0: outflow).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/vec3.h"

namespace obscura::smoke {

enum CellClass : std::uint8_t {
    kFluid = 0,  // simulated
    kSolid = 1,  // brush, mesh, moving obstacle, out of the level, or sealed off from the centre
    kOpen = 2,   // ghost layer cell open to the outside: pressure 0, density 0 (smoke leaves here)
};

struct GridInfo {
    Vec3 origin;          // world position of the grid's minimum corner (metres)
    int nx = 0, ny = 0, nz = 0;
    double cellSize = 0;  // metres

    std::size_t cells() const { return static_cast<std::size_t>(nx) * ny * nz; }
    std::size_t index(int i, int j, int k) const {
        return static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(ny) * k);
    }
    Vec3 cellCentre(int i, int j, int k) const {
        return origin + Vec3{(i + 0.5) * cellSize, (j + 0.5) * cellSize, (k + 0.5) * cellSize};
    }
    Vec3 size() const { return Vec3{nx * cellSize, ny * cellSize, nz * cellSize}; }
    // Continuous cell coordinates of a world point: the centre of cell (i, j, k) maps to (i, j, k).
    Vec3 toCellCoords(const Vec3& p) const { return (p - origin) / cellSize - Vec3{0.5, 0.5, 0.5}; }
    bool contains(int i, int j, int k) const { return i >= 0 && j >= 0 && k >= 0 && i < nx && j < ny && k < nz; }
};

}  // namespace obscura::smoke
