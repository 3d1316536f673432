// Signs placed in a .map (engine_ext/decals/decal_sign.h): tests/decals/levels/bad_signs.map holds
// a good text sign, a good image sign, a repeat of the text, and one bad sign per reason; each bad
// one is skipped with "file:line: decal_sign skipped: <why>" at the line where its entity opens,
// the good ones are placed facing where their angle says, the repeat shares its tile, and the
// atlas's bound skips what does not fit with a message.
#include <gtest/gtest.h>

#include "entity_lines.h"

#include "decals/decal_sign.h"
#include "map/map_compile.h"

#include <filesystem>
#include <fstream>
#include <map>

using namespace obscura;
using namespace obscura::decals;
namespace fs = std::filesystem;

namespace {
const fs::path kLevels = fs::path(OBSCURA_SOURCE_DIR) / "tests/decals/levels";
const std::string kMap = (kLevels / "bad_signs.map").string();

// The line of the entity after each "// <why>" comment.
std::map<std::string, int> entityLines() { return test::entityLinesAfterComments(kMap); }

struct Loaded {
    std::vector<SignSpec> specs;
    SignAtlas atlas;
    std::vector<std::string> warnings;
};

Loaded load(int maxTiles = kSignMaxTiles) {
    Loaded l;
    const map::Level level = map::loadLevel(kMap);
    l.specs = readSigns(level, {kLevels.string()}, l.warnings);
    l.atlas = bakeSigns(l.specs, OBSCURA_DECAL_FONT, l.warnings, maxTiles);
    return l;
}

bool hasWarning(const Loaded& l, int line, const std::string& why) {
    const std::string head = kMap + ":" + std::to_string(line) + ": decal_sign skipped: ";
    for (const auto& w : l.warnings)
        if (w.rfind(head, 0) == 0 && w.find(why) != std::string::npos) return true;
    return false;
}

std::string all(const Loaded& l) {
    std::string s;
    for (const auto& w : l.warnings) s += w + "\n";
    return s;
}
}  // namespace

TEST(DecalSign, EveryBadSignIsSkippedWithItsLineAndReason) {
    const Loaded l = load();
    const auto lines = entityLines();
    const std::map<std::string, std::string> reasons = {
        {"missing image", "image 'no_such.png' not found"},
        {"image outside the level's folder and the media", "outside the level's folder and the media folders"},
        {"not a PNG (found, refused when baked)", "PNG"},
        {"zero size", "size 0 m is outside (0, 16]"},
        {"negative size", "size -2 m is outside (0, 16]"},
        {"huge size", "size 1e9 m is outside (0, 16]"},
        {"non-finite origin", "non-finite origin"},
        {"non-finite angle", "non-finite angle"},
        {"non-finite mangle", "non-finite mangle"},
        {"empty text", "empty text"},
        {"unknown style", "unknown style 'sparkle'"},
        {"both text and image", "both 'text' and 'image'"},
        {"neither", "neither 'text' nor 'image'"},
        {"bad depth", "depth 0 m is outside (0, 4]"},
    };
    for (const auto& [what, why] : reasons) {
        ASSERT_TRUE(lines.count(what)) << what;
        EXPECT_TRUE(hasWarning(l, lines.at(what), why)) << what << " (line " << lines.at(what) << ", expected '" << why << "'):\n" << all(l);
    }
    EXPECT_EQ(l.warnings.size(), reasons.size()) << all(l);
}

TEST(DecalSign, GoodSignsArePlacedAndARepeatSharesItsTile) {
    const Loaded l = load();
    ASSERT_EQ(l.atlas.decals.size(), 3u) << all(l);
    EXPECT_EQ(l.atlas.tileCount(), 2);  // "EXIT" (twice) and the mask
    ASSERT_EQ(l.atlas.tiles.height, DECAL_TILE);
    const Decal &text = l.atlas.decals[0], &image = l.atlas.decals[1], &again = l.atlas.decals[2];
    EXPECT_EQ(text.tile, DECAL_TILES);
    EXPECT_EQ(image.tile, DECAL_TILES + 1);
    EXPECT_EQ(again.tile, DECAL_TILES);
    // Quake angle 270 faces south (-y): our +z. Origin (160 255 64) / 32 -> (5, 2, -7.97).
    EXPECT_NEAR(text.normal.x, 0, 1e-9);
    EXPECT_NEAR(text.normal.z, 1, 1e-9);
    EXPECT_NEAR(text.position.x, 5, 1e-9);
    EXPECT_NEAR(text.position.y, 2, 1e-9);
    EXPECT_NEAR(text.position.z, -255.0 / 32, 1e-9);
    EXPECT_EQ(text.width, 1.2);
    EXPECT_EQ(again.width, 1.0);   // the default size
    EXPECT_EQ(text.depth, 0.2);    // the default depth
    EXPECT_NEAR(text.colour.y, 200.0 / 255, 1e-9);  // 0..255 colours scaled
    EXPECT_TRUE(text.tinted);
    EXPECT_TRUE(text.style & static_cast<int>(DECAL_STYLE_MSDF));
    EXPECT_TRUE(text.style & static_cast<int>(DECAL_STYLE_OUTLINE));
    EXPECT_FALSE(image.style & static_cast<int>(DECAL_STYLE_MSDF));
    for (const auto& d : l.atlas.decals) EXPECT_EQ(validate(d), "");
    // The tiles are fields: the mask's cross has inside (> 128) and outside (< 128) texels.
    int inside = 0, outside = 0;
    for (int y = 0; y < DECAL_TILE; ++y)
        for (int x = DECAL_TILE; x < 2 * DECAL_TILE; ++x)
            (l.atlas.tiles.rgba[(static_cast<std::size_t>(y) * l.atlas.tiles.width + x) * 4 + 3] > 128 ? inside : outside)++;
    EXPECT_GT(inside, 300);
    EXPECT_GT(outside, 1000);
}

TEST(DecalSign, TheAtlasBoundSkipsWhatDoesNotFit) {
    const Loaded l = load(1);  // room for one tile: the image sign does not fit, the repeat does
    ASSERT_EQ(l.atlas.decals.size(), 2u) << all(l);
    EXPECT_EQ(l.atlas.tileCount(), 1);
    const auto lines = entityLines();
    EXPECT_TRUE(hasWarning(l, lines.at("good image"), "more than 1 distinct sign texts and images")) << all(l);
}
