// Image comparison for the replay test bench: SSIM on luma (Wang, Bovik, Sheikh, Simoncelli,
// "Image Quality Assessment: From Error Visibility to Structural Similarity", IEEE TIP 2004;
// 11x11 Gaussian window, sigma 1.5, C1 = (0.01*255)^2, C2 = (0.03*255)^2), PSNR on RGB, the
// largest channel difference and the count of pixels over a threshold; an amplified difference
// heat map. Plain C++.
#pragma once

#include "core/image.h"

#include <string>
#include <vector>

namespace obscura::imagecmp {

using obscura::Image;
using obscura::ImageError;

struct Metrics {
    double ssim = 1;          // mean SSIM of the luma (Rec. 709 weights)
    double psnr = 0;          // dB over RGB; +infinity when identical
    int maxChannelDiff = 0;   // 0..255
    long pixelsOver = 0;      // pixels whose largest channel difference exceeds the threshold
};

struct Tolerance {
    // 0.99: a reviewed frame re-rendered by the same Mesa stays above 0.999; shifting a textured
    // frame by one pixel or blurring it 3x3 drops it below 0.97.
    double minSsim = 0.99;
    // 35 dB: about 4.5 grey levels of RMS error, invisible. A one-pixel shift of a smooth
    // textured frame can still score ~36 dB: SSIM, not PSNR, is what catches shifts and blurs.
    double minPsnr = 35;
    int maxChannelDiff = 255;  // not limited by default: single pixels may differ a lot (HUD text)
    // 0: strict by default, any clearly changed pixel fails; a test whose references may be
    // re-rendered by another GL driver raises it (the replay tests allow 400 edge pixels).
    long maxPixelsOver = 0;
    // 16/255 (about 6 %): differences up to this are rounding and filtering noise between GL
    // drivers and barely visible; larger ones mean the content of the pixel changed.
    int pixelThreshold = 16;
};

// Throws ImageError when the sizes differ or an image is empty or malformed.
Metrics compare(const Image& reference, const Image& actual, int pixelThreshold = 16);
// Names of the metrics that fail the tolerance, with their values (empty when it passes).
std::vector<std::string> failures(const Metrics& m, const Tolerance& t);
// Per-pixel largest channel difference, multiplied by `amplify`, as a black-red-yellow-white heat map.
Image diffHeatmap(const Image& reference, const Image& actual, double amplify = 8);

std::string formatMetrics(const Metrics& m);  // "ssim=0.99871 psnr=41.20 maxdiff=37 over=12"

}  // namespace obscura::imagecmp
