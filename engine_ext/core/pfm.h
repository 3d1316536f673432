// Float RGB images as PFM (Portable Float Map: "PF\n<w> <h>\n<scale>\n", then w x h x 3 float32,
// rows bottom to top, little-endian when the scale is negative): the game's HDR dumps (its
// half-resolution volume buffer, its lit surfaces) and tools/signref's reference.
#pragma once

#include "core/image.h"

#include <string>
#include <vector>

namespace obscura {

struct FloatImage {
    int width = 0, height = 0;
    std::vector<float> rgb;  // width * height * 3, row-major, TOP row first (flipped on I/O)
};

// Writes little-endian ("-1.0"); throws ImageError naming the file.
void writePfm(const FloatImage& image, const std::string& path);
// Reads "PF" (rgb) and "Pf" (grey, copied to the three channels), either byte order; throws
// ImageError naming the file and what is wrong with it.
FloatImage readPfm(const std::string& path);

}  // namespace obscura
