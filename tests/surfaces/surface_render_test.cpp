// Sky and fence faces rendered by the game (tests/replay/scripts/fence_sky.replay on
// tests/surfaces/levels/fence_sky.map, 640 x 360), checked on the captured pixels:
// - the fence's holes show the red brick wall behind it (an opaque fence shows none);
// - its sun shadow on the floor has holes: lit and shadowed texels side by side in the band
//   (an opaque caster leaves the band all dark);
// - the e1u1/sky1 roof is drawn by the sky material: looking up, the zenith colour of
//   shaders/level/sky.frag, flat (a tiled, lit texture has clouds and shading).
#include <gtest/gtest.h>

#include "core/image.h"
#include "run_process.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <vector>

using namespace obscura;
namespace fs = std::filesystem;

namespace {
struct Rgb {
    int r, g, b;
};

// The captures, made once for all tests.
const fs::path& captures() {
    static const fs::path dir = [] {
        const fs::path d = fs::temp_directory_path() / ("obscura_surfaces_" + std::to_string(getpid()));
        fs::create_directories(d);
        const std::string cmd = "cd " + std::string(OBSCURA_SOURCE_DIR) + " && XDG_CACHE_HOME=" + (d / "cache").string() + " " +
                                OBSCURA_GAME + " --replay tests/replay/scripts/fence_sky.replay --capture-dir " + d.string();
        const auto r = testing_support::runProcess(cmd);
        EXPECT_EQ(r.code, 0) << r.out;
        return d;
    }();
    return dir;
}

// Pixels of a capture inside [x0, x1) x [y0, y1), skipping the crosshair (40 x 40 at the centre).
std::vector<Rgb> region(const std::string& capture, int x0, int x1, int y0, int y1) {
    const Image img = readPng((captures() / (capture + ".png")).string());
    EXPECT_EQ(img.width, 640);
    EXPECT_EQ(img.height, 360);
    std::vector<Rgb> out;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            if (std::abs(x - 320) < 20 && std::abs(y - 180) < 20) continue;
            const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) * 4;
            out.push_back({img.rgba[i], img.rgba[i + 1], img.rgba[i + 2]});
        }
    return out;
}

double fraction(const std::vector<Rgb>& px, const std::function<bool(const Rgb&)>& f) {
    return static_cast<double>(std::count_if(px.begin(), px.end(), f)) / static_cast<double>(std::max<std::size_t>(px.size(), 1));
}

double luma(const Rgb& p) { return 0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b; }
}  // namespace

TEST(SurfacesRender, TheBrickWallShowsThroughTheFencesHoles) {
    // The middle of the fence (it spans x 160..480, y 40..225 of the frame).
    const auto px = region("fence", 200, 440, 60, 200);
    // Brick by its hue, not its brightness: the wall behind stands in the baked shade (its light
    // the sky and the bounce, engine_ext/lightbake), a dark red of about (73, 43, 34).
    const double brick = fraction(px, [](const Rgb& p) { return p.r > 1.3 * p.g && p.r > 1.3 * p.b && p.r > 20; });
    const double bars = fraction(px, [](const Rgb& p) { return p.g > p.r + 10; });  // the generated grille is teal
    // The grille covers 61 % of the texture (texgen.cpp), the holes 39 %; edges blend a little.
    EXPECT_GT(brick, 0.25) << "the wall behind the fence should show through its holes";
    EXPECT_GT(bars, 0.45) << "the fence's bars";
}

TEST(SurfacesRender, TheFencesShadowHasHoles) {
    // Looking 15 degrees down: the shadow band lies at y 150..185; open floor in the sun below it.
    std::vector<double> lit;
    for (const Rgb& p : region("shadow", 100, 540, 250, 300)) lit.push_back(luma(p));
    std::nth_element(lit.begin(), lit.begin() + static_cast<long>(lit.size() / 2), lit.end());
    const double sunlit = lit[lit.size() / 2];
    const auto band = region("shadow", 100, 540, 150, 185);
    const double dark = fraction(band, [&](const Rgb& p) { return luma(p) < 0.75 * sunlit; });
    const double bright = fraction(band, [&](const Rgb& p) { return luma(p) > 0.9 * sunlit; });
    EXPECT_GT(dark, 0.3) << "the bars' shadow";
    EXPECT_GT(bright, 0.2) << "sunlight through the holes onto the floor";
}

TEST(SurfacesRender, TheSkyNamedE1u1Sky1IsDrawnAsTheSky) {
    // Straight up the sky gradient is the zenith colour (shaders/level/sky.frag's 0.36 0.52 0.78,
    // shown as is: 92 133 199), the same on every pixel of the roof in view.
    const auto px = region("sky", 150, 500, 130, 330);
    const double zenith = fraction(px, [](const Rgb& p) {
        return std::abs(p.r - 92) <= 3 && std::abs(p.g - 133) <= 3 && std::abs(p.b - 199) <= 3;
    });
    EXPECT_GT(zenith, 0.99);
}
