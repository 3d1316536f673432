// See image.h.
#include "core/image.h"

#include <png.h>

#include <cstdio>
#include <memory>

namespace obscura {

namespace {
using FilePtr = std::unique_ptr<FILE, int (*)(FILE*)>;
}  // namespace

Image readPng(const std::string& path) {
    FilePtr f(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!f) throw ImageError(path + ": cannot open PNG");
    unsigned char sig[8];
    if (std::fread(sig, 1, 8, f.get()) != 8 || png_sig_cmp(sig, 0, 8)) throw ImageError(path + ": not a PNG file");
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        png_destroy_read_struct(&png, &info, nullptr);
        throw ImageError(path + ": libpng initialisation failed");
    }
    // Everything with a destructor lives before setjmp: a longjmp back here must not skip one.
    Image im;
    std::vector<png_bytep> rows;
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        throw ImageError(path + ": corrupt PNG");
    }
    png_init_io(png, f.get());
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    // Whatever the file holds, read RGBA8.
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_gray_to_rgb(png);
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    png_read_update_info(png, info);
    im.width = static_cast<int>(png_get_image_width(png, info));
    im.height = static_cast<int>(png_get_image_height(png, info));
    im.rgba.resize(static_cast<std::size_t>(im.width) * im.height * 4);
    rows.resize(static_cast<std::size_t>(im.height));
    for (int y = 0; y < im.height; ++y) rows[static_cast<std::size_t>(y)] = &im.rgba[static_cast<std::size_t>(y) * im.width * 4];
    png_read_image(png, rows.data());
    png_destroy_read_struct(&png, &info, nullptr);
    return im;
}

void writePng(const Image& im, const std::string& path) {
    FilePtr f(std::fopen(path.c_str(), "wb"), &std::fclose);
    if (!f) throw ImageError(path + ": cannot open for writing");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        png_destroy_write_struct(&png, &info);
        throw ImageError(path + ": libpng initialisation failed");
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw ImageError(path + ": PNG write failed");
    }
    png_init_io(png, f.get());
    png_set_IHDR(png, info, static_cast<png_uint_32>(im.width), static_cast<png_uint_32>(im.height), 8, PNG_COLOR_TYPE_RGBA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < im.height; ++y)
        png_write_row(png, const_cast<png_bytep>(&im.rgba[static_cast<std::size_t>(y) * im.width * 4]));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
}

}  // namespace obscura
