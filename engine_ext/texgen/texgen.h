// Procedural level textures, generated from a texture's name: keywords in the name pick a style
// (brick, concrete, plaster, tile, metal, wood/crate, stone, grass, sky, liquids, light panels);
// any other name gets a muted colour from its hash with faint noise and a grid so scale reads.
// Deterministic (seeded from the name) and seamlessly tiling (every noise octave is periodic
// over the image). Plain C++: used by the build-time tool and for runtime fallbacks.
#pragma once

#include "core/image.h"

#include <cstdint>
#include <string>

namespace obscura::texgen {

std::uint32_t nameHash(const std::string& name);  // FNV-1a 32-bit of the lower-cased name
Image generateTexture(const std::string& textureName, int size = 128);

}  // namespace obscura::texgen
