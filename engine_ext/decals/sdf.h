// Distance fields for alpha-tested decals (Green, "Improved Alpha-Tested Magnification for Vector
// Textures and Special Effects", SIGGRAPH 2007) and their multi-channel variant (Chlumský,
// "Shape Decomposition for Multi-channel Distance Fields", 2015). Plain C++, no OGRE.
//
//   mask (high resolution, binary)  --exact EDT (Felzenszwalb & Huttenlocher 2012)-->  signed
//   distance in high-res pixels  --point-sampled at the low-res texel centres, / factor-->  low-res
//   SDF in low-res texels  --0.5 + d / (2 range)-->  8 bits.
// The multi-channel field is computed from the vector outline itself (Shape): per channel the
// pseudo-distance to the nearest edge of that channel's colour; the median of the three keeps a
// corner where a single channel would round it off.
// Sign convention everywhere: distance > 0 inside the shape.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace obscura::decals {

struct BakeError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A binary mask, row-major, top row first; 1 = inside.
struct Mask {
    int width = 0, height = 0;
    std::vector<std::uint8_t> inside;
    bool at(int x, int y) const { return inside[static_cast<std::size_t>(y) * width + x] != 0; }
};

// A float field (distances, coverage), row-major, top row first.
struct Field {
    int width = 0, height = 0;
    std::vector<float> v;
    float at(int x, int y) const { return v[static_cast<std::size_t>(y) * width + x]; }
    // Bilinear, clamped at the border, at pixel coordinates (pixel centres at i + 0.5).
    float bilinear(double x, double y) const;
};

// Closed polygon contours in unit coordinates (0..1 across the tile, y down), nonzero winding.
struct Point {
    double x = 0, y = 0;
};
struct Shape {
    std::vector<std::vector<Point>> contours;
};

// --- the exact Euclidean distance transform -------------------------------------------------
// Squared distance from each pixel centre to the nearest pixel centre where `feature` is set
// (Felzenszwalb & Huttenlocher, "Distance Transforms of Sampled Functions": the lower envelope of
// parabolas, one pass per axis, O(pixels)). With no feature pixel at all: every value is huge.
std::vector<float> squaredEdt(const std::vector<std::uint8_t>& feature, int width, int height);
// Signed distance in pixels to the mask's boundary (half a pixel beyond the last inside centre),
// > 0 inside.
Field signedDistance(const Mask& mask);

// --- masks -------------------------------------------------------------------------------------
// Largest mask edge and area the baker accepts (bounded memory: a mask costs 9 bytes a pixel).
constexpr int kMaxMaskEdge = 8192;
constexpr long long kMaxMaskPixels = 4096LL * 4096LL;
// A PNG's mask: alpha >= 128 when the image has varying alpha, else luminance >= 128. Checks the
// header's size against the limits before decoding. Throws BakeError naming the file.
Mask maskFromPng(const std::string& path);
// Scan-converts `shape` at size x size (nonzero winding, sampled at pixel centres).
Mask rasterize(const Shape& shape, int size);
// The same at width x height pixels, a shape unit being `pixelsPerUnit` pixels (the square one is
// rasterize(shape, size, size, size)): the shape's (0, 0) at the top-left corner, y down.
Mask rasterize(const Shape& shape, int width, int height, double pixelsPerUnit);
// Simple vector shapes in unit coordinates: a disc; a square (rotated by `degrees` about the centre);
// a ring; a star with `points` points.
Shape circleShape(double cx, double cy, double r, int segments = 256);
Shape squareShape(double cx, double cy, double half, double degrees = 0);
Shape ringShape(double cx, double cy, double outer, double inner, int segments = 256);
Shape starShape(double cx, double cy, double outer, double inner, int points);

// --- the low-resolution fields -------------------------------------------------------------------
// The signed distance of a size*factor mask at size x size, in low-res texels.
Field downsampleSdf(const Field& highRes, int size);
// The plain bitmap of the same size: the mask's coverage of each low-res texel (box filter), 0..1.
Field coverage(const Mask& mask, int size);
// Multi-channel field of `shape` at size x size, in low-res texels (3 fields: r, g, b).
struct Msdf {
    Field r, g, b;
};
Msdf multiChannel(const Shape& shape, int size);
// Clash correction (after Chlumský's): where the median of the three channels is more than
// `tolerance` texels from the true distance `sdf` at a texel or at any of its 4 neighbours, or where
// bilinear filtering between two texels of a 2x2 cell would put a false edge (the median of the
// blended channels across the edge from the blended true distance, by more than `tolerance`), the
// texels fall back to the true distance in all three channels. Returns the number changed.
int correctClashes(Msdf& m, const Field& sdf, double tolerance = 1.0);
// 8-bit encoding: 0.5 + d / (2 range), clamped (range in texels: the spread).
std::uint8_t encode(double distance, double range);
double decode(std::uint8_t value, double range);

// --- the quality measure ------------------------------------------------------------------------
// A field magnified `magnification` times (bilinear), thresholded: where its contour lies
// compared with the true one. `lowRes(x, y)` returns the value at low-res pixel coordinates, with
// the edge at `threshold` and inside above it; `trueDistance(u, v)` the exact signed distance at
// unit coordinates, in units of the tile. The crossings of the threshold along every row and column
// of the magnified image are found (linear between samples) and the true distance measured there.
struct EdgeError {
    double mean = 0, max = 0;  // in magnified pixels
    int crossings = 0;
};
EdgeError edgeError(int lowResSize, int magnification, double threshold,
                    const std::function<double(double, double)>& lowRes,
                    const std::function<double(double, double)>& trueDistance,
                    const std::function<bool(double, double)>& where = {});

}  // namespace obscura::decals
