#include "aoref/ao_compare.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace obscura::aoref {

AoError compareAo(const std::vector<float>& reference, const std::vector<std::uint8_t>& hit,
                  const std::vector<float>& mode, double occludedBelow) {
    if (reference.size() != hit.size() || reference.size() != mode.size())
        throw std::invalid_argument("compareAo: the reference, its hit mask and the mode differ in size");
    // In the reference's precision, so a reference of 0.95f is not below a threshold of 0.95.
    const float below = static_cast<float>(occludedBelow);
    double sum = 0, sum2 = 0, bias = 0, occSum = 0, occBias = 0;
    AoError e;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        if (!hit[i]) continue;
        const double d = static_cast<double>(mode[i]) - reference[i];
        sum += std::fabs(d);
        sum2 += d * d;
        bias += d;
        ++e.pixels;
        if (reference[i] < below) {
            occSum += std::fabs(d);
            occBias += d;
            ++e.occludedPixels;
        }
    }
    if (e.pixels) {
        e.mae = sum / e.pixels;
        e.rmse = std::sqrt(sum2 / e.pixels);
        e.bias = bias / e.pixels;
    }
    if (e.occludedPixels) {
        e.occludedMae = occSum / e.occludedPixels;
        e.occludedBias = occBias / e.occludedPixels;
    }
    return e;
}

std::vector<float> whiteAo(std::size_t pixels) { return std::vector<float>(pixels, 1.0f); }

std::vector<float> aoFromRgba8(const std::vector<std::uint8_t>& rgba) {
    std::vector<float> ao(rgba.size() / 4);
    for (std::size_t i = 0; i < ao.size(); ++i) ao[i] = static_cast<float>(rgba[i * 4] / 255.0);
    return ao;
}

std::vector<float> boxAverage(const std::vector<float>& image, int width, int height, int s) {
    if (s < 1 || width <= 0 || height <= 0 || width % s || height % s ||
        image.size() != static_cast<std::size_t>(width) * height)
        throw std::invalid_argument("boxAverage: the block must divide the image's sides");
    const int w = width / s, h = height / s;
    std::vector<float> out(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sum = 0;
            for (int j = 0; j < s; ++j)
                for (int i = 0; i < s; ++i) sum += image[static_cast<std::size_t>(y * s + j) * width + x * s + i];
            out[static_cast<std::size_t>(y) * w + x] = static_cast<float>(sum / (s * s));
        }
    return out;
}

std::string formatAoError(const AoError& e) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "mae=%.5f rmse=%.5f bias=%.5f pixels=%ld occluded_mae=%.5f occluded_bias=%.5f occluded_pixels=%ld "
                  "occluded_share=%.4f",
                  e.mae, e.rmse, e.bias, e.pixels, e.occludedMae, e.occludedBias, e.occludedPixels, e.occludedShare());
    return line;
}

}  // namespace obscura::aoref
