// The smoke as the frame saw it, frozen for tools/signref (issue 15): the live volumes' density
// grids, the noise's time and the extinction per density unit. A text header, then raw float32:
//
//   obscura-smoke-dump 1
//   time <smokeTime seconds> sigma <smokeSigma per metre>
//   volumes <N>
//   volume <nx> <ny> <nz> <origin x> <origin y> <origin z> <cellSize>
//   <nx*ny*nz little-endian float32 densities, x fastest, then y, then z, right after the newline>
//   ... (the next "volume" line follows the floats)
//
// origin: world metres of the grid's min corner; cell (i, j, k)'s centre is
// origin + (i + 0.5, j + 0.5, k + 0.5) cellSize.
#pragma once

#include "core/vec3.h"

#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace obscura::smoke {

struct DumpVolume {
    int nx = 0, ny = 0, nz = 0;
    Vec3 origin;
    double cellSize = 0;
    std::vector<float> density;  // nx * ny * nz, x fastest

    // Trilinear between cell centres, clamped to the outermost centres inside the grid's box; 0
    // outside the box.
    double densityAt(const Vec3& p) const;
};

struct SmokeDump {
    double time = 0;   // seconds: smoke_march.glsl's smokeTime
    double sigma = 0;  // per metre per density unit: its smokeSigma
    std::vector<DumpVolume> volumes;
};

struct DumpError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws DumpError "<name>: <what is wrong>" (the line or the volume it is in).
SmokeDump readSmokeDump(std::istream& in, const std::string& name);
SmokeDump readSmokeDump(const std::string& path);
void writeSmokeDump(const SmokeDump& dump, std::ostream& out);
void writeSmokeDump(const SmokeDump& dump, const std::string& path);  // throws DumpError naming the file

}  // namespace obscura::smoke
