// Procedural level textures, generated from a texture's name: keywords in the lower-cased name
// pick a style (brick/brk, concrete/cement, plaster/wall, tile, metal/plate/tech, wood/crate/plank,
// stone/rock/cobble, grass/ground/dirt, sky, `*`-prefixed liquids (*water, *lava, *slime), light
// panels); any other name gets a muted colour from its hash with faint noise and a grid so scale
// reads. Value noise and fBm written here (Perlin 1985 / Musgrave's fBm, on a wrapping lattice),
// seeded through obscura::Rng from the name's FNV-1a hash: deterministic, and seamlessly tiling
// (every octave and pattern is periodic over the image). Colours are sRGB albedo in a realistic
// range (about 0.2..0.8, never pure black or white). Plain C++: used by the build-time tool
// (tools/texgen) and for runtime fallbacks. PNG output: obscura::writePng in core/image.h.
#pragma once

#include "core/image.h"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace obscura::texgen {

struct TexgenError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

constexpr int kMinSize = 8;     // below this the patterns (mortar lines, grids) no longer fit
constexpr int kMaxSize = 2048;  // 16 MB of RGBA: anything larger is a mistake for a tiling texture

std::uint32_t nameHash(const std::string& name);  // FNV-1a 32-bit of the lower-cased name
// A size x size RGBA8 image (top row first, alpha 255; a fence name, `{` first, gets a grille:
// alpha 0 in its holes). Throws TexgenError if size is outside kMinSize..kMaxSize.
Image generateTexture(const std::string& textureName, int size = 128);

}  // namespace obscura::texgen
