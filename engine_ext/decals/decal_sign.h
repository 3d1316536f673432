// Signage decals placed in a .map: the point entity `decal_sign` (in TrenchBroom a point entity
// with these keys; the project has no entity definition file yet), projected onto the wall behind
// it at level load, never recycled. Plain C++.
//
// Keys: `text` (FreeType glyphs -> a multi-channel field) or `image` (a PNG mask, found like a
// misc_model: beside the level, in the data folder or the working directory, and confined to the
// level's folder and the media folders), `size` (metres, the square's side; default 1), `angle`
// (degrees, Quake's yaw: the way the sign faces) or `mangle` ("pitch yaw roll" degrees, Quake's:
// pitch down positive, roll turns the sign about its facing), `depth` (metres of projection,
// default 0.2: 10 cm either side of the wall), `_color` ("r g b", 0..1 or 0..255),
// `style` (words, combinable: alpha, smooth, outline, glow, shadow; default smooth).
//
// A bad sign is skipped with "file:line: decal_sign skipped: <why>"; the level loads without it.
#pragma once

#include "core/image.h"
#include "decals/decal_list.h"
#include "map/level.h"

#include <string>
#include <vector>

namespace obscura::decals {

// Accepted ranges (their reasons in decal_sign.cpp).
constexpr double kSignMaxSize = 16, kSignMaxDepth = 4;
constexpr std::size_t kSignMaxText = 32;
// Tiles the signs may add to the atlas (distinct texts and images).
constexpr int kSignMaxTiles = DECAL_MAX_TILES - DECAL_TILES;

struct SignSpec {
    std::string where;      // "file:line" of the entity
    std::string text;       // either this
    std::string imageFile;  // or this (the resolved, confined path)
    Decal decal;            // placed; its tile is set by bakeSigns
};

// Every valid decal_sign of `level`, in file order; `searchDirs` as Session::modelSearchDirs.
// Skipped ones add a message to `warnings`.
std::vector<SignSpec> readSigns(const map::Level& level, const std::vector<std::string>& searchDirs,
                                std::vector<std::string>& warnings);

struct SignAtlas {
    Image tiles;                // DECAL_TILE * n x DECAL_TILE: atlas tiles DECAL_TILES .. DECAL_TILES + n - 1
    std::vector<Decal> decals;  // one a sign that was baked, its tile set
    int tileCount() const { return tiles.width / DECAL_TILE; }
};

// One tile per distinct text or image (the same text on two signs shares a tile), at most
// `maxTiles`; a sign beyond them, or whose mask or font cannot be baked, is skipped with a message.
SignAtlas bakeSigns(const std::vector<SignSpec>& signs, const std::string& fontPath, std::vector<std::string>& warnings,
                    int maxTiles = kSignMaxTiles);

}  // namespace obscura::decals
