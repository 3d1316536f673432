// See atlas.h.
#include "decals/atlas.h"

#include "decals/decals_shared.h"
#include "decals/glyph.h"

#include <cmath>

namespace obscura::decals {

namespace {
void put(Image& atlas, int tile, int size, int x, int y, int channel, double distance) {
    atlas.rgba[(static_cast<std::size_t>(y) * atlas.width + tile * size + x) * 4 + channel] = encode(distance, DECAL_RANGE);
}
}  // namespace

void bakeShapeTile(Image& atlas, int tile, int size, int factor, const Shape& shape) {
    const Field sdf = downsampleSdf(signedDistance(rasterize(shape, size * factor)), size);
    Msdf m = multiChannel(shape, size);
    correctClashes(m, sdf);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            put(atlas, tile, size, x, y, 0, m.r.at(x, y));
            put(atlas, tile, size, x, y, 1, m.g.at(x, y));
            put(atlas, tile, size, x, y, 2, m.b.at(x, y));
            put(atlas, tile, size, x, y, 3, sdf.at(x, y));
        }
}

void bakeMaskTile(Image& atlas, int tile, int size, const Mask& mask) {
    if (mask.width != mask.height) throw BakeError("a decal mask must be square (it is " + std::to_string(mask.width) +
                                                   " x " + std::to_string(mask.height) + ")");
    const Field sdf = downsampleSdf(signedDistance(mask), size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            for (int c = 0; c < 4; ++c) put(atlas, tile, size, x, y, c, sdf.at(x, y));
}

Shape tileShape(int tile, const std::string& fontPath) {
    switch (tile) {
        case DECAL_TILE_BULLET: return starShape(0.5, 0.5, 0.44, 0.31, 11);
        case DECAL_TILE_SCORCH: {  // an irregular blot: a radius wandering with a few fixed harmonics
            Shape blot;
            blot.contours.emplace_back();
            for (int i = 0; i < 128; ++i) {
                const double a = 6.283185307179586 * i / 128;
                const double r = 0.33 + 0.05 * std::sin(3 * a + 1) + 0.04 * std::sin(7 * a + 2) + 0.03 * std::sin(13 * a + 0.5) +
                                 0.02 * std::sin(23 * a + 4);
                blot.contours.back().push_back({0.5 + r * std::cos(a), 0.5 + r * std::sin(a)});
            }
            return blot;
        }
        case DECAL_TILE_SIGN: return textShape(fontPath, "EXIT", 0.08);
        case DECAL_TILE_SQUARE: return squareShape(0.5, 0.5, 0.40);
    }
    throw BakeError("no decal tile " + std::to_string(tile));
}

Image bakeAtlas(const std::string& fontPath) {
    Image atlas;
    atlas.width = DECAL_TILE * DECAL_TILES;
    atlas.height = DECAL_TILE;
    atlas.rgba.assign(static_cast<std::size_t>(atlas.width) * atlas.height * 4, 0);
    for (int t = 0; t < DECAL_TILES; ++t) bakeShapeTile(atlas, t, DECAL_TILE, DECAL_BAKE_FACTOR, tileShape(t, fontPath));
    return atlas;
}

}  // namespace obscura::decals
