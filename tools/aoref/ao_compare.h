// The error of an AO image against the ray-traced reference (plain C++, no Embree): over the whole
// frame (every pixel that sees geometry) and over the occluded region only (the pixels whose
// reference AO is below a threshold, 0.95 by default) — the whole-frame figure alone rewards
// leaving things white, because most of a frame is barely occluded.
// tools/aoref/main.cpp prints these for each --compare image and for `off` (an all-white frame).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace obscura::aoref {

// A pixel belongs to the occluded region when its reference AO is below this.
constexpr double kOccludedBelow = 0.95;

struct AoError {
    // Whole frame: over the pixels that see geometry. Differences are mode - reference, so a
    // positive bias is a frame that is too light.
    double mae = 0, rmse = 0, bias = 0;
    long pixels = 0;
    // Occluded region: over the pixels that see geometry with reference < occludedBelow.
    double occludedMae = 0, occludedBias = 0;
    long occludedPixels = 0;
    double occludedShare() const { return pixels ? static_cast<double>(occludedPixels) / pixels : 0.0; }
};

// reference, hit and mode are row-major images of the same size (throws std::invalid_argument if
// not); mode and reference in 0..1 (1 = unoccluded); hit is 1 where the pixel sees geometry.
AoError compareAo(const std::vector<float>& reference, const std::vector<std::uint8_t>& hit,
                  const std::vector<float>& mode, double occludedBelow = kOccludedBelow);

// The `off` frame: no AO, every pixel 1.
std::vector<float> whiteAo(std::size_t pixels);

// A grey RGBA8 image's red channel as AO in 0..1 (what the game's AO-only capture holds).
std::vector<float> aoFromRgba8(const std::vector<std::uint8_t>& rgba);

// The mean over s x s blocks of a row-major width x height image: the (width/s) x (height/s) image
// a pixel of which is the average of the s x s pixels it covers (a box filter, the pixel's area).
// The table traces the truth and renders the game at s times the scored size and scores both
// averaged down, so each scored pixel is its footprint's average AO in both. Throws
// std::invalid_argument unless s >= 1 divides both sides and the image is width x height.
std::vector<float> boxAverage(const std::vector<float>& image, int width, int height, int s);

// One line: "mae=... rmse=... bias=... pixels=... occluded_mae=... occluded_bias=...
// occluded_pixels=... occluded_share=..." (tools/aoref/ao_table.sh reads these keys).
std::string formatAoError(const AoError& e);

}  // namespace obscura::aoref
