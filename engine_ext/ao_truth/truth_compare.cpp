// See truth_compare.h.
#include "ao_truth/truth_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace obscura::ao_truth {

Score score(const ssao::AoImage& reference, const std::vector<float>& modeAo) {
    Score s;
    s.mode = aoref::compareAo(reference.ao, reference.hit, modeAo);
    s.off = aoref::compareAo(reference.ao, reference.hit, aoref::whiteAo(reference.ao.size()));
    return s;
}

std::vector<float> resampleNearest(const std::vector<float>& src, int sw, int sh, int dw, int dh) {
    std::vector<float> out(static_cast<std::size_t>(dw) * dh);
    for (int y = 0; y < dh; ++y) {
        const int sy = std::min(sh - 1, static_cast<int>((y + 0.5) * sh / dh));
        for (int x = 0; x < dw; ++x) {
            const int sx = std::min(sw - 1, static_cast<int>((x + 0.5) * sw / dw));
            out[static_cast<std::size_t>(y) * dw + x] = src[static_cast<std::size_t>(sy) * sw + sx];
        }
    }
    return out;
}

std::array<std::uint8_t, 4> heatColour(double e) {
    const double k = std::min(1.0, std::fabs(e) / kHeatFullScale);
    // Blue (too dark) and orange (too light): apart for the common red-green colour blindnesses.
    const double r = e > 0 ? 1.0 : 0.1, g = e > 0 ? 0.55 : 0.45, b = e > 0 ? 0.0 : 1.0;
    auto c = [k](double v) { return static_cast<std::uint8_t>(std::lround(255.0 * v * k)); };
    return {c(r), c(g), c(b), 255};
}

std::vector<std::uint8_t> greyRgba(const std::vector<float>& ao) {
    std::vector<std::uint8_t> out(ao.size() * 4, 255);
    for (std::size_t i = 0; i < ao.size(); ++i) {
        const auto v = static_cast<std::uint8_t>(std::lround(std::clamp(ao[i], 0.0f, 1.0f) * 255.0f));
        out[i * 4] = out[i * 4 + 1] = out[i * 4 + 2] = v;
    }
    return out;
}

std::vector<std::uint8_t> heatMapRgba(const ssao::AoImage& reference, const std::vector<float>& modeAo) {
    std::vector<std::uint8_t> out(reference.ao.size() * 4);
    for (std::size_t i = 0; i < reference.ao.size(); ++i) {
        const auto c = reference.hit[i] ? heatColour(static_cast<double>(modeAo.at(i)) - reference.ao[i]) : kHeatSky;
        std::copy(c.begin(), c.end(), out.begin() + static_cast<std::ptrdiff_t>(i * 4));
    }
    return out;
}

namespace {
std::string fixed3(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", v);
    return text;
}
}  // namespace

std::vector<std::string> hudLines(const HudFacts& f) {
    // Short lines: the HUD of a 320 x 180 capture holds about 44 characters.
    if (f.show == Show::Off) return {};
    char line[160];
    std::vector<std::string> lines;
    const char* what = f.show == Show::Reference ? "reference" : f.show == Show::Mode ? "mode's AO" : "heat map";
    if (f.rays < f.totalRays)
        std::snprintf(line, sizeof line, "truth (T): %s %dx%d %d/%d rays", what, f.width, f.height, f.rays, f.totalRays);
    else
        std::snprintf(line, sizeof line, "truth (T): %s %dx%d %d rays", what, f.width, f.height, f.rays);
    lines.emplace_back(line);
    if (f.score) {
        const Score& s = *f.score;
        // Words, not symbols: "error" is the mean absolute difference from the truth; the occluded
        // pixels' line says which way the mode errs there ("too light": it misses occlusion).
        const std::string at = s.rays < f.totalRays ? " (vs " + std::to_string(s.rays) + " rays)" : std::string();
        std::snprintf(line, sizeof line, "%s: error %.3f%s", f.mode.c_str(), s.mode.mae, at.c_str());
        if (f.mode != "off") {  // off's own lines follow
            lines.emplace_back(line);
            const double b = s.mode.occludedBias;
            const std::string way = std::abs(b) < 0.0005 ? "no bias" : (b > 0 ? "too light " : "too dark ") + fixed3(std::abs(b));
            std::snprintf(line, sizeof line, " occluded: error %.3f, %s", s.mode.occludedMae, way.c_str());
            lines.emplace_back(line);
        }
        std::snprintf(line, sizeof line, "off: error %.3f, occluded (%.0f%%) %.3f", s.off.mae, 100.0 * s.off.occludedShare(),
                      s.off.occludedMae);
        lines.emplace_back(line);
    }
    if (f.show == Show::HeatMap) {
        lines.emplace_back("heat: mode - truth, black 0,");
        std::snprintf(line, sizeof line, "blue -%.1f (darker), orange +%.1f", kHeatFullScale, kHeatFullScale);
        lines.emplace_back(line);
    }
    return lines;
}

}  // namespace obscura::ao_truth
