// What the truth key shows and says (plain C++): the cycle of what is shown, the active mode's AO
// against the traced reference (tools/aoref/ao_compare.h: whole frame, occluded region, bias,
// beside `off`'s), the heat map of mode - truth, and the HUD's lines.
#pragma once

#include "ao_truth/truth_show.h"
#include "aoref/ao_compare.h"
#include "ssao/ao_reference.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace obscura::ao_truth {

struct Score {
    aoref::AoError mode, off;  // the active mode's AO and an all-white frame, against the reference
    int rays = 0;              // the reference's rays per pixel when scored
};
Score score(const ssao::AoImage& reference, const std::vector<float>& modeAo);

// `src` (sw x sh, row-major, top row first) sampled at the centres of a dw x dh image's pixels
// (nearest): the mode's AO buffer at the reference's size (the identity when they match).
std::vector<float> resampleNearest(const std::vector<float>& src, int sw, int sh, int dw, int dh);

// The heat map's colours: mode - truth below zero (the mode darker than the truth: occlusion
// that is not there) is blue, above zero (lighter: occlusion missed) is orange; black where they
// agree, at full colour from an error of kHeatFullScale; sky pixels (no truth) dark grey.
// 0.5: the occluded region's worst modes are off by 0.2-0.3 on average (ssao/README.md), which
// shows at half to two thirds of full colour; a crease a mode misses entirely saturates.
constexpr double kHeatFullScale = 0.5;
std::array<std::uint8_t, 4> heatColour(double modeMinusTruth);
// Sky: no truth there; a dark grey apart from the black of agreement.
constexpr std::array<std::uint8_t, 4> kHeatSky = {40, 40, 40, 255};

// RGBA8 images at the reference's size, top row first: the reference's AO as grey, and the heat map.
std::vector<std::uint8_t> greyRgba(const std::vector<float>& ao);
std::vector<std::uint8_t> heatMapRgba(const ssao::AoImage& reference, const std::vector<float>& modeAo);

// The HUD's lines: what is shown and the reference's progress (rays per pixel so far), then, once
// scored, the mode's whole-frame and occluded-region MAE and the occluded region's bias (mode -
// truth: + is too light) ("@64": scored against a 64-ray
// reference) and off's below it with the occluded region's share of the pixels that see
// geometry, and for the heat map its scale.
struct HudFacts {
    Show show = Show::Off;
    std::string mode;    // the active AO mode ("horizon")
    int width = 0, height = 0;
    int rays = 0, totalRays = 0;  // the reference's rays per pixel so far, and when finished
    const Score* score = nullptr; // null until the mode was read back against a reference
};
std::vector<std::string> hudLines(const HudFacts& facts);

}  // namespace obscura::ao_truth
