// The decal atlas: what each tile holds (shaders/decals/decals_shared.h) baked into one RGBA8
// image. Plain C++.
#pragma once

#include "core/image.h"
#include "decals/sdf.h"

#include <string>

namespace obscura::decals {

// One tile (size x size texels) from a vector shape: A = the EDT of its rasterisation at
// size * factor, RGB = its multi-channel field.
void bakeShapeTile(Image& atlas, int tile, int size, int factor, const Shape& shape);
// One tile from a mask (no outline): A = RGB = the EDT of the mask, whose width and height must
// be size * factor... or any size: the field is resampled.
void bakeMaskTile(Image& atlas, int tile, int size, const Mask& mask);
// The whole atlas; text from `fontPath`.
Image bakeAtlas(const std::string& fontPath);
// The vector shapes of the atlas's tiles (for the tests); the sign's needs the font.
Shape tileShape(int tile, const std::string& fontPath);

}  // namespace obscura::decals
