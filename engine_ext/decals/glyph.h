// Text as a vector shape, from a TrueType/OpenType font through FreeType: the outlines of each
// glyph (quadratic and cubic curves flattened into short lines), laid out along a line with the
// font's advances, then fitted into the unit tile (or kept at its size in em units). Plain C++ (FreeType, no OGRE).
#pragma once

#include "decals/sdf.h"

#include <string>

namespace obscura::decals {

// `text` (ASCII/Latin-1 bytes) in the font at `fontPath`, scaled to fit the unit tile inside
// `margin` on every side, centred. Throws BakeError naming the font or the character.
Shape textShape(const std::string& fontPath, const std::string& text, double margin);

// The same text at its real size: em units (1 = the font's em, what a letter height in metres
// scales), y up, the pen from x = 0 on the baseline; x0..x1, y0..y1 its outlines' box. The
// back-lit signs (engine_ext/signs) lay their plates out from it. Throws BakeError as textShape.
struct TextLayout {
    Shape shape;
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
TextLayout textLayout(const std::string& fontPath, const std::string& text);

}  // namespace obscura::decals
