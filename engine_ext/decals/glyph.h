// Text as a vector shape, from a TrueType/OpenType font through FreeType: the outlines of each
// glyph (quadratic and cubic curves flattened into short lines), laid out along a line with the
// font's advances, then fitted into the unit tile. Plain C++ (FreeType, no OGRE).
#pragma once

#include "decals/sdf.h"

#include <string>

namespace obscura::decals {

// `text` (ASCII/Latin-1 bytes) in the font at `fontPath`, scaled to fit the unit tile inside
// `margin` on every side, centred. Throws BakeError naming the font or the character.
Shape textShape(const std::string& fontPath, const std::string& text, double margin);

}  // namespace obscura::decals
