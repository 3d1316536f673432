// An 8-bit RGBA image and its PNG I/O (libpng): what the texture generator writes, the image
// comparison reads and writes.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace obscura {

struct ImageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // RGBA8, row-major, top row first
};

Image readPng(const std::string& path);  // any PNG, converted to RGBA8; throws ImageError naming the file
void writePng(const Image& image, const std::string& path);  // throws ImageError naming the file

}  // namespace obscura
