// See imagecmp.h.
#include "imagecmp/imagecmp.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

namespace obscura::imagecmp {

namespace {
std::string sizeText(const Image& im) { return std::to_string(im.width) + "x" + std::to_string(im.height); }

// Both images non-empty, of one size, with as many bytes as their size says (never read past them).
void checkPair(const Image& a, const Image& b) {
    for (const Image* im : {&a, &b}) {
        if (im->width <= 0 || im->height <= 0) throw ImageError("empty image (" + sizeText(*im) + ")");
        if (im->rgba.size() != static_cast<std::size_t>(im->width) * static_cast<std::size_t>(im->height) * 4)
            throw ImageError("image of " + sizeText(*im) + " holds " + std::to_string(im->rgba.size()) +
                             " bytes, expected width*height*4");
    }
    if (a.width != b.width || a.height != b.height)
        throw ImageError("image sizes differ: " + sizeText(a) + " vs " + sizeText(b));
}

std::vector<double> luma(const Image& im) {
    std::vector<double> y(static_cast<std::size_t>(im.width) * im.height);
    for (std::size_t i = 0; i < y.size(); ++i) {
        const std::uint8_t* p = &im.rgba[i * 4];
        y[i] = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    }
    return y;
}

// Separable Gaussian blur (11 taps, sigma 1.5, as in Wang et al.), clamping at the borders.
std::vector<double> blur(const std::vector<double>& src, int w, int h) {
    static const std::vector<double> kernel = [] {
        std::vector<double> k(11);
        double sum = 0;
        for (int i = 0; i < 11; ++i) sum += k[static_cast<std::size_t>(i)] = std::exp(-(i - 5) * (i - 5) / (2 * 1.5 * 1.5));
        for (auto& v : k) v /= sum;
        return k;
    }();
    std::vector<double> tmp(src.size()), out(src.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double s = 0;
            for (int k = -5; k <= 5; ++k) s += kernel[static_cast<std::size_t>(k + 5)] * src[static_cast<std::size_t>(y * w + std::clamp(x + k, 0, w - 1))];
            tmp[static_cast<std::size_t>(y * w + x)] = s;
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double s = 0;
            for (int k = -5; k <= 5; ++k) s += kernel[static_cast<std::size_t>(k + 5)] * tmp[static_cast<std::size_t>(std::clamp(y + k, 0, h - 1) * w + x)];
            out[static_cast<std::size_t>(y * w + x)] = s;
        }
    return out;
}

double ssim(const Image& a, const Image& b) {
    const int w = a.width, h = a.height;
    const auto x = luma(a), y = luma(b);
    std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        xx[i] = x[i] * x[i];
        yy[i] = y[i] * y[i];
        xy[i] = x[i] * y[i];
    }
    const auto mx = blur(x, w, h), my = blur(y, w, h), sxx = blur(xx, w, h), syy = blur(yy, w, h), sxy = blur(xy, w, h);
    const double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
    double sum = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double vx = sxx[i] - mx[i] * mx[i], vy = syy[i] - my[i] * my[i], cxy = sxy[i] - mx[i] * my[i];
        sum += ((2 * mx[i] * my[i] + c1) * (2 * cxy + c2)) / ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
    }
    return sum / static_cast<double>(x.size());
}
}  // namespace

Metrics compare(const Image& a, const Image& b, int threshold) {
    checkPair(a, b);
    Metrics m;
    double se = 0;
    const std::size_t n = static_cast<std::size_t>(a.width) * a.height;
    for (std::size_t i = 0; i < n; ++i) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(a.rgba[i * 4 + c]) - int(b.rgba[i * 4 + c]));
            se += double(d) * d;
            worst = std::max(worst, d);
        }
        m.maxChannelDiff = std::max(m.maxChannelDiff, worst);
        m.pixelsOver += worst > threshold;
    }
    const double mse = se / (3.0 * static_cast<double>(n));
    m.psnr = mse == 0 ? std::numeric_limits<double>::infinity() : 10 * std::log10(255.0 * 255.0 / mse);
    m.ssim = m.maxChannelDiff == 0 ? 1.0 : ssim(a, b);
    return m;
}

std::vector<std::string> failures(const Metrics& m, const Tolerance& t) {
    std::vector<std::string> f;
    char buf[160];
    if (m.ssim < t.minSsim) {
        std::snprintf(buf, sizeof buf, "SSIM %.5f < %.5f", m.ssim, t.minSsim);
        f.emplace_back(buf);
    }
    if (m.psnr < t.minPsnr) {
        std::snprintf(buf, sizeof buf, "PSNR %.2f dB < %.2f dB", m.psnr, t.minPsnr);
        f.emplace_back(buf);
    }
    if (m.maxChannelDiff > t.maxChannelDiff) {
        std::snprintf(buf, sizeof buf, "max channel difference %d > %d", m.maxChannelDiff, t.maxChannelDiff);
        f.emplace_back(buf);
    }
    if (m.pixelsOver > t.maxPixelsOver) {
        std::snprintf(buf, sizeof buf, "%ld pixels differ by more than %d > %ld allowed", m.pixelsOver, t.pixelThreshold, t.maxPixelsOver);
        f.emplace_back(buf);
    }
    return f;
}

Image diffHeatmap(const Image& a, const Image& b, double amplify) {
    checkPair(a, b);
    if (!(amplify > 0) || !std::isfinite(amplify)) throw ImageError("heat map amplification " + std::to_string(amplify) + ", expected a positive number");
    Image out{a.width, a.height, std::vector<std::uint8_t>(a.rgba.size())};
    for (std::size_t i = 0; i < a.rgba.size() / 4; ++i) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.rgba[i * 4 + c]) - int(b.rgba[i * 4 + c])));
        const double t = std::min(1.0, worst * amplify / 255.0);
        // black -> red -> yellow -> white
        out.rgba[i * 4 + 0] = static_cast<std::uint8_t>(std::lround(255 * std::min(1.0, t * 3)));
        out.rgba[i * 4 + 1] = static_cast<std::uint8_t>(std::lround(255 * std::clamp(t * 3 - 1, 0.0, 1.0)));
        out.rgba[i * 4 + 2] = static_cast<std::uint8_t>(std::lround(255 * std::clamp(t * 3 - 2, 0.0, 1.0)));
        out.rgba[i * 4 + 3] = 255;
    }
    return out;
}

std::string formatMetrics(const Metrics& m) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "ssim=%.5f psnr=%.2f maxdiff=%d over=%ld", m.ssim, m.psnr, m.maxChannelDiff, m.pixelsOver);
    return buf;
}

}  // namespace obscura::imagecmp
