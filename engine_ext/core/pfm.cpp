// See pfm.h.
#include "core/pfm.h"

#include "core/byte_order.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

namespace obscura {

namespace {
// One whitespace-separated header token; PFM allows any whitespace between them.
std::string token(std::istream& in) {
    std::string t;
    in >> t;
    return t;
}
}  // namespace

void writePfm(const FloatImage& image, const std::string& path) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3)
        throw ImageError(path + ": cannot write a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                         " PFM from " + std::to_string(image.rgb.size()) + " floats");
    std::ofstream out(path, std::ios::binary);
    if (!out) throw ImageError(path + ": cannot open for writing");
    out << "PF\n" << image.width << " " << image.height << "\n-1.0\n";
    const bool swap = !hostLittleEndian();
    std::vector<float> row(static_cast<std::size_t>(image.width) * 3);
    for (int y = image.height - 1; y >= 0; --y) {  // bottom row first
        const float* src = image.rgb.data() + static_cast<std::size_t>(y) * image.width * 3;
        for (std::size_t i = 0; i < row.size(); ++i) row[i] = swap ? byteSwapped(src[i]) : src[i];
        out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size() * sizeof(float)));
    }
    if (!out) throw ImageError(path + ": write failed");
}

FloatImage readPfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ImageError(path + ": cannot open");
    const std::string magic = token(in);
    if (magic != "PF" && magic != "Pf") throw ImageError(path + ": not a PFM (starts with '" + magic.substr(0, 8) + "', expected PF or Pf)");
    const int channels = magic == "PF" ? 3 : 1;
    long w = 0, h = 0;
    double scale = 0;
    std::string ws = token(in), hs = token(in), ss = token(in);
    try {
        std::size_t n = 0;
        w = std::stol(ws, &n);
        if (n != ws.size()) throw std::invalid_argument(ws);
        h = std::stol(hs, &n);
        if (n != hs.size()) throw std::invalid_argument(hs);
        scale = std::stod(ss, &n);
        if (n != ss.size()) throw std::invalid_argument(ss);
    } catch (const std::exception&) {
        throw ImageError(path + ": bad PFM header (size '" + ws + " " + hs + "', scale '" + ss + "')");
    }
    if (w <= 0 || h <= 0 || w > 65536 || h > 65536) throw ImageError(path + ": bad PFM size " + ws + "x" + hs);
    if (scale == 0 || !std::isfinite(scale)) throw ImageError(path + ": bad PFM scale '" + ss + "'");
    in.get();  // the single whitespace character that ends the header
    const bool fileLittle = scale < 0;
    const bool swap = fileLittle != hostLittleEndian();
    const std::size_t count = static_cast<std::size_t>(w) * h * channels;
    std::vector<float> data(count);
    in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(count * sizeof(float)));
    if (static_cast<std::size_t>(in.gcount()) != count * sizeof(float))
        throw ImageError(path + ": PFM data ends after " + std::to_string(in.gcount()) + " of " +
                         std::to_string(count * sizeof(float)) + " bytes");
    FloatImage img;
    img.width = static_cast<int>(w);
    img.height = static_cast<int>(h);
    img.rgb.resize(static_cast<std::size_t>(w) * h * 3);
    for (long y = 0; y < h; ++y) {
        const std::size_t srcRow = static_cast<std::size_t>(h - 1 - y) * w * channels;  // bottom row first in the file
        for (long x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                float f = data[srcRow + static_cast<std::size_t>(x) * channels + (channels == 3 ? c : 0)];
                img.rgb[(static_cast<std::size_t>(y) * w + x) * 3 + c] = swap ? byteSwapped(f) : f;
            }
    }
    return img;
}

}  // namespace obscura
