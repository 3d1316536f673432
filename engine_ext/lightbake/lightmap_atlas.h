// Where each level face keeps its baked light: a chart per face (a grid of texels on the face's
// plane, LIGHTBAKE_CHART_BORDER texels wider on every side), shelf-packed into one atlas. Plain C++.
//
// A chart's texel (i, j) covers the square whose centre is
//   origin + s * (sMin + (i + 0.5 - border) * texel) + t * (tMin + (j + 0.5 - border) * texel),
// so the face's own extent [sMin, sMax] x [tMin, tMax] starts one border in, and bilinear filtering
// anywhere on the face reads only texels of its own chart.
#pragma once

#include "map/level.h"

#include <cstddef>
#include <string>
#include <vector>

namespace obscura::lightbake {

// A face that the bake lights: a visible, non-sky, non-liquid face of a static (non-mover) brush.
struct FaceRef {
    int brush = 0, face = 0;
};

struct Chart {
    FaceRef ref;
    Vec3 normal;        // the face's, unit
    Vec3 s, t;          // unit axes on the face's plane
    double planeD = 0;  // dot(normal, any point of the face)
    double sMin = 0, tMin = 0;
    int x = 0, y = 0;  // its corner in the atlas, texels
    int w = 0, h = 0;  // its size, texels, border included
};

struct Atlas {
    double texel = 0.25;  // metres a texel
    int width = 0, height = 0;
    std::vector<Chart> charts;
    std::size_t texels() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
    // The atlas coordinates, in texels (0..width, 0..height), of a point on chart c's face.
    void atlasCoord(const Chart& c, const Vec3& p, double& u, double& v) const;
    // The world point at the centre of chart texel (i, j) (border included), on the face's plane.
    Vec3 texelCentre(const Chart& c, int i, int j) const;
    // Bilinear read of `values` (`channels` floats a texel, the whole atlas) at a point of chart c's
    // face, as the GPU filters it (clamped to the chart).
    void bilinear(const std::vector<float>& values, int channels, const Chart& c, const Vec3& p, float* out) const;
};

// Texels a lightmap atlas may hold: 4 Mi (2048 x 2048) keeps both baked maps at 64 MiB in half floats.
constexpr std::size_t kMaxAtlasTexels = std::size_t(1) << 22;
// Widest atlas row, texels (every GL 3.3 GPU takes 8192; 4096 keeps the atlas nearly square).
constexpr int kMaxAtlasWidth = 4096;

// Whether the bake lights this face (FaceRef's rule).
bool bakedFace(const map::LevelBrush& brush, const map::LevelPolygon& face);

// Charts every baked face at `texel` metres; when the charts do not fit kMaxAtlasTexels the texel
// grows by a quarter until they do, and `note` (if given) says so, naming the limit.
Atlas buildAtlas(const map::Level& level, double texel, std::string* note = nullptr);

}  // namespace obscura::lightbake
