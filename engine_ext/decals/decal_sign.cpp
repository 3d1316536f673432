// See decal_sign.h.
#include "decals/decal_sign.h"

#include "decals/atlas.h"
#include "decals/glyph.h"
#include "decals/sdf.h"
#include "map/asset_path.h"
#include "map/entity_values.h"

#include <cmath>
#include <map>
#include <sstream>

namespace obscura::decals {

namespace {
// Defaults: a 1 m plate; 20 cm deep, 10 cm either side of the wall: wider than a brush face's
// placement error in a hand-made map (a few cm), thinner than any wall the arena has (0.5 m), so
// a sign never comes through on the other side. The colour: the atlas's old sign tile's off-white.
constexpr double kDefaultSize = 1, kDefaultDepth = 0.2;
const Vec3 kDefaultColour{0.92, 0.9, 0.85};
// Limits: a sign over 16 m a side is no sign (the arena's longest wall is 48 m; LibreQuake's
// biggest texts are ~6 m); 4 m of depth would reach through rooms. 32 characters: the tile is a
// 64^2 square, so a longer line's letters would be under 2 texels tall, below what a distance
// field can hold (Green: features a few texels wide).
// Text is fitted inside this margin of its tile (as the build's "EXIT" tile).
constexpr double kTextMargin = 0.08;

// The strict readers the back-lit signs share (map/entity_values.h).
std::vector<std::string> words(const std::string& s) { return map::valueWords(s); }
bool numbers(const std::string& text, std::size_t n, double* out) { return map::valueNumbers(text, n, out); }
std::string quoted(const std::string& s) { return map::quotedValue(s); }

struct Skip {
    std::string why;
};

SignSpec readSign(const map::Level& level, const map::LevelEntity& e, const std::vector<std::string>& searchDirs) {
    SignSpec s;
    Decal& d = s.decal;
    d.tinted = true;
    d.colour = kDefaultColour;
    d.opacity = 1;
    // Where: the compiled origin, but the raw key decides (a non-number may have been read as 0).
    if (std::string why = map::readOrigin(e, d.position); !why.empty()) throw Skip{why};

    // Facing: `mangle` or `angle` (map/entity_values.h: the normal is the orientation's facing).
    map::Orientation turn;
    if (std::string why = map::readOrientation(e, turn); !why.empty()) throw Skip{why};
    d.normal = turn.facing;
    d.angle = turn.roll;

    auto metres = [&](const char* key, double fallback, double hi) {
        if (!e.has(key)) return fallback;
        double m = 0;
        if (!numbers(e.value(key), 1, &m)) throw Skip{std::string("'") + key + "' is " + quoted(e.value(key)) + ", expected metres"};
        if (!std::isfinite(m) || m <= 0 || m > hi) {
            std::ostringstream os;
            os << key << " " << e.value(key) << " m is outside (0, " << hi << "]";
            throw Skip{os.str()};
        }
        return m;
    };
    d.width = d.height = metres("size", kDefaultSize, kSignMaxSize);
    d.depth = metres("depth", kDefaultDepth, kSignMaxDepth);

    if (std::string why = map::readColour(e, "_color", d.colour); !why.empty()) throw Skip{why};

    d.style = static_cast<int>(DECAL_STYLE_SMOOTH);
    if (e.has("style")) {
        d.style = 0;
        const auto names = words(e.value("style"));
        if (names.empty()) throw Skip{"empty style"};
        for (const auto& n : names) {
            if (n == "alpha") continue;  // the plain alpha test: no smooth bit
            else if (n == "smooth") d.style |= static_cast<int>(DECAL_STYLE_SMOOTH);
            else if (n == "outline") d.style |= static_cast<int>(DECAL_STYLE_OUTLINE);
            else if (n == "glow") d.style |= static_cast<int>(DECAL_STYLE_GLOW);
            else if (n == "shadow") d.style |= static_cast<int>(DECAL_STYLE_SHADOW);
            else throw Skip{"unknown style " + quoted(n) + ", expected alpha, smooth, outline, glow or shadow"};
        }
    }

    const bool hasText = e.has("text"), hasImage = e.has("image");
    if (hasText == hasImage) throw Skip{hasText ? "both 'text' and 'image'" : "neither 'text' nor 'image'"};
    if (hasText) {
        s.text = e.value("text");
        if (words(s.text).empty()) throw Skip{"empty text"};
        if (s.text.size() > kSignMaxText) throw Skip{"text longer than " + std::to_string(kSignMaxText) + " characters"};
        d.style |= static_cast<int>(DECAL_STYLE_MSDF);  // glyph outlines: sharp corners
    } else {
        const std::string& name = e.value("image");
        if (name.empty()) throw Skip{"empty 'image'"};
        const map::AssetPath found = map::resolveAsset(name, searchDirs, map::levelAssetRoots(level.sourcePath, searchDirs));
        if (!found.error.empty()) throw Skip{"image " + quoted(name) + " " + found.error + "; images must live there"};
        if (found.file.empty()) throw Skip{"image " + quoted(name) + " not found (looked beside the level, in the data folder and the working directory)"};
        s.imageFile = found.file;
    }
    return s;
}
}  // namespace

std::vector<SignSpec> readSigns(const map::Level& level, const std::vector<std::string>& searchDirs,
                                std::vector<std::string>& warnings) {
    std::vector<SignSpec> out;
    for (const auto& e : level.entities) {
        if (e.classname != "decal_sign") continue;
        const std::string where = e.where(level.sourcePath);
        try {
            SignSpec s = readSign(level, e, searchDirs);
            s.where = where;
            out.push_back(std::move(s));
        } catch (const Skip& skip) {
            warnings.push_back(where + ": decal_sign skipped: " + skip.why);
        }
    }
    return out;
}

SignAtlas bakeSigns(const std::vector<SignSpec>& signs, const std::string& fontPath, std::vector<std::string>& warnings,
                    int maxTiles) {
    std::map<std::string, int> tileOf;  // "text:..." / "image:<file>" -> tile (ordered: the same atlas every load)
    std::vector<Image> baked;
    SignAtlas out;
    for (const auto& s : signs) {
        const std::string key = s.text.empty() ? "image:" + s.imageFile : "text:" + s.text;
        auto it = tileOf.find(key);
        if (it == tileOf.end()) {
            if (static_cast<int>(baked.size()) >= maxTiles) {
                warnings.push_back(s.where + ": decal_sign skipped: more than " + std::to_string(maxTiles) +
                                   " distinct sign texts and images (the atlas holds " + std::to_string(DECAL_MAX_TILES) +
                                   " tiles, " + std::to_string(DECAL_TILES) + " of them the game's)");
                continue;
            }
            Image tile;
            tile.width = tile.height = DECAL_TILE;
            tile.rgba.assign(static_cast<std::size_t>(DECAL_TILE) * DECAL_TILE * 4, 0);
            try {
                if (!s.text.empty()) bakeShapeTile(tile, 0, DECAL_TILE, DECAL_BAKE_FACTOR, textShape(fontPath, s.text, kTextMargin));
                else bakeMaskTile(tile, 0, DECAL_TILE, maskFromPng(s.imageFile));
            } catch (const std::exception& e) {  // BakeError, ImageError: a bad mask or font
                warnings.push_back(s.where + ": decal_sign skipped: " + e.what());
                continue;
            }
            it = tileOf.emplace(key, static_cast<int>(baked.size())).first;
            baked.push_back(std::move(tile));
        }
        Decal d = s.decal;
        d.tile = DECAL_TILES + it->second;
        out.decals.push_back(d);
    }
    out.tiles.width = DECAL_TILE * static_cast<int>(baked.size());
    out.tiles.height = DECAL_TILE;
    out.tiles.rgba.assign(static_cast<std::size_t>(out.tiles.width) * DECAL_TILE * 4, 0);
    for (std::size_t t = 0; t < baked.size(); ++t)
        for (int y = 0; y < DECAL_TILE; ++y)
            std::copy_n(baked[t].rgba.begin() + static_cast<std::ptrdiff_t>(y) * DECAL_TILE * 4, DECAL_TILE * 4,
                        out.tiles.rgba.begin() + (static_cast<std::ptrdiff_t>(y) * out.tiles.width + static_cast<std::ptrdiff_t>(t) * DECAL_TILE) * 4);
    return out;
}

}  // namespace obscura::decals
