// See glyph.h.
#include "decals/glyph.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <cmath>
#include <memory>

namespace obscura::decals {

namespace {
constexpr int kCurveSteps = 12;
constexpr int kUnitsPerEm = 256;  // the outlines' scale (FT_Set_Char_Size at 72 dpi)  // lines per curve: <= 8 degrees of turn each for a quarter circle

struct Builder {
    Shape shape;
    Point pen;
    double offsetX = 0;
    Point at(const FT_Vector* v) const { return {offsetX + v->x / 64.0, v->y / 64.0}; }
};

int moveTo(const FT_Vector* to, void* user) {
    auto& b = *static_cast<Builder*>(user);
    b.shape.contours.emplace_back();
    b.pen = b.at(to);
    b.shape.contours.back().push_back(b.pen);
    return 0;
}
int lineTo(const FT_Vector* to, void* user) {
    auto& b = *static_cast<Builder*>(user);
    b.pen = b.at(to);
    b.shape.contours.back().push_back(b.pen);
    return 0;
}
int conicTo(const FT_Vector* control, const FT_Vector* to, void* user) {
    auto& b = *static_cast<Builder*>(user);
    const Point p0 = b.pen, p1 = b.at(control), p2 = b.at(to);
    for (int i = 1; i <= kCurveSteps; ++i) {
        const double t = static_cast<double>(i) / kCurveSteps, u = 1 - t;
        b.shape.contours.back().push_back({u * u * p0.x + 2 * u * t * p1.x + t * t * p2.x, u * u * p0.y + 2 * u * t * p1.y + t * t * p2.y});
    }
    b.pen = p2;
    return 0;
}
int cubicTo(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    auto& b = *static_cast<Builder*>(user);
    const Point p0 = b.pen, p1 = b.at(c1), p2 = b.at(c2), p3 = b.at(to);
    for (int i = 1; i <= kCurveSteps; ++i) {
        const double t = static_cast<double>(i) / kCurveSteps, u = 1 - t;
        const double w0 = u * u * u, w1 = 3 * u * u * t, w2 = 3 * u * t * t, w3 = t * t * t;
        b.shape.contours.back().push_back({w0 * p0.x + w1 * p1.x + w2 * p2.x + w3 * p3.x, w0 * p0.y + w1 * p1.y + w2 * p2.y + w3 * p3.y});
    }
    b.pen = p3;
    return 0;
}

// The outlines at 256 units to the em (y up, the pen from x = 0 on the baseline) and their box.
struct Raw {
    Shape shape;
    double x0 = 1e30, y0 = 1e30, x1 = -1e30, y1 = -1e30;
};

Raw rawOutlines(const std::string& fontPath, const std::string& text) {
    if (text.empty()) throw BakeError("text decal: the text is empty");
    FT_Library lib = nullptr;
    if (FT_Init_FreeType(&lib)) throw BakeError("text decal: FreeType does not start");
    std::unique_ptr<FT_LibraryRec_, FT_Error (*)(FT_Library)> libGuard(lib, &FT_Done_FreeType);
    FT_Face face = nullptr;
    if (FT_New_Face(lib, fontPath.c_str(), 0, &face)) throw BakeError(fontPath + ": not a font FreeType can read");
    std::unique_ptr<FT_FaceRec_, FT_Error (*)(FT_Face)> faceGuard(face, &FT_Done_Face);
    FT_Set_Char_Size(face, 0, kUnitsPerEm * 64, 72, 72);  // 256 units to the em, in 26.6

    Builder b;
    FT_Outline_Funcs funcs{};
    funcs.move_to = moveTo;
    funcs.line_to = lineTo;
    funcs.conic_to = conicTo;
    funcs.cubic_to = cubicTo;
    for (unsigned char c : text) {
        const FT_UInt index = FT_Get_Char_Index(face, c);
        if (index == 0 && c != ' ') throw BakeError(fontPath + ": no glyph for '" + std::string(1, static_cast<char>(c)) + "'");
        if (FT_Load_Glyph(face, index, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
            throw BakeError(fontPath + ": cannot load the glyph for '" + std::string(1, static_cast<char>(c)) + "'");
        if (face->glyph->format == FT_GLYPH_FORMAT_OUTLINE) FT_Outline_Decompose(&face->glyph->outline, &funcs, &b);
        b.offsetX += face->glyph->advance.x / 64.0;
    }
    // Drop the closing point a contour repeats, and degenerate contours.
    Raw r;
    Shape& s = r.shape;
    double &x0 = r.x0, &y0 = r.y0, &x1 = r.x1, &y1 = r.y1;
    for (auto& c : b.shape.contours) {
        if (c.size() > 1 && c.front().x == c.back().x && c.front().y == c.back().y) c.pop_back();
        if (c.size() < 3) continue;
        for (const Point& p : c) {
            x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
        }
        s.contours.push_back(c);
    }
    if (s.contours.empty()) throw BakeError("text decal: '" + text + "' has no outline in " + fontPath);
    return r;
}
}  // namespace

Shape textShape(const std::string& fontPath, const std::string& text, double margin) {
    Raw r = rawOutlines(fontPath, text);
    Shape& s = r.shape;
    const double x0 = r.x0, y0 = r.y0, x1 = r.x1, y1 = r.y1;
    // Fit into the tile, y down.
    const double scale = (1 - 2 * margin) / std::max(x1 - x0, y1 - y0);
    const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    for (auto& c : s.contours)
        for (Point& p : c) p = {0.5 + (p.x - cx) * scale, 0.5 - (p.y - cy) * scale};
    return s;
}

TextLayout textLayout(const std::string& fontPath, const std::string& text) {
    Raw r = rawOutlines(fontPath, text);
    constexpr double kEm = 1.0 / kUnitsPerEm;  // a power of two: the scaling is exact
    TextLayout t;
    t.shape = std::move(r.shape);
    for (auto& c : t.shape.contours)
        for (Point& p : c) p = {p.x * kEm, p.y * kEm};
    t.x0 = r.x0 * kEm, t.y0 = r.y0 * kEm, t.x1 = r.x1 * kEm, t.y1 = r.y1 * kEm;
    return t;
}

}  // namespace obscura::decals
