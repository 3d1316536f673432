// Level lighting in the real game, headless, read back through the G-buffer views: the direct light
// at each light's foot against map/quake_light.h (the C++ model of level.frag), worldspawn
// _minlight as the ambient, and a floor face reached by 40 lights (OGRE hands a pass 8), every one
// of them lighting its own foot; an env_ambient scaling the ambient inside its box only. Levels:
// tests/lighting/levels (make_levels.py).
#include <gtest/gtest.h>

#include "core/image.h"
#include "lightbake/light_bake.h"
#include "map/map_compile.h"
#include "map/quake_light.h"
#include "run_process.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace obscura;
using obscura::testing_support::ProcessResult;

namespace {
constexpr double kPi = 3.14159265358979323846;
const std::string kLevels = std::string(OBSCURA_SOURCE_DIR) + "/tests/lighting/levels/";

struct Shot {
    Image image;
    Vec3 eye;
    double yaw = 0, pitch = 0;  // degrees, as the game prints them
    std::string out;
};

// The game at `pose` ('x y z yaw pitch'), one tick, showing `view`; the pose it really rendered
// from is read back from its `camera-pose` line.
Shot shoot(const std::string& level, const std::string& pose, const std::string& view, const std::string& name,
           int width = 160, int height = 90) {
    const std::string png = (fs::path(testing::TempDir()) / ("lighting_" + name + ".png")).string();
    const ProcessResult r = testing_support::runProcess(std::string("'" OBSCURA_GAME "' --headless --ticks 1 --hud off --ssao off") +
                                                        " --width " + std::to_string(width) + " --height " + std::to_string(height) +
                                                        " --level '" + kLevels + level + "' --start-pose '" + pose + "' --view " +
                                                        view + " --screenshot " + png);
    EXPECT_EQ(r.code, 0) << r.out;
    Shot s;
    s.out = r.out;
    s.image = readPng(png);
    const auto at = r.out.find("camera-pose ");
    EXPECT_NE(at, std::string::npos) << r.out;
    if (at != std::string::npos) std::istringstream(r.out.substr(at + 12)) >> s.eye.x >> s.eye.y >> s.eye.z >> s.yaw >> s.pitch;
    return s;
}

// The views show x / 4, gamma-encoded (shaders/gbuffer_view): back to linear x.
double decodeQuarter(double v8) { return 4.0 * std::pow(v8 / 255.0, 2.2); }

// The 3x3 mean of the red channel around the centre pixel.
double centre(const Image& im) {
    double sum = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) sum += im.rgba[(static_cast<std::size_t>(im.height / 2 + dy) * im.width + im.width / 2 + dx) * 4];
    return sum / 9;
}

// Where the view's centre ray meets the floor (y = 0): yaw about +Y with 0 facing -Z, pitch up.
Vec3 floorPoint(const Shot& s) {
    const double yaw = s.yaw * kPi / 180, pitch = s.pitch * kPi / 180;
    const Vec3 forward{-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
    return s.eye + forward * (-s.eye.y / forward.y);
}

// The direct irradiance the C++ model gives at a floor point (sum over every light, floored by
// delay 4 lights; there are none in these levels).
double model(const map::Level& level, const Vec3& p) {
    double sum = 0;
    for (const auto& l : level.lights) sum += map::lightAt(l, p, {0, 1, 0});
    return std::max(sum, 0.0);
}
}  // namespace

TEST(LightingRender, DirectLightAtEachFootMatchesQuakeFalloff) {
    const map::Level level = map::loadLevel(kLevels + "falloff.map");
    ASSERT_EQ(level.lights.size(), 6u);
    ASSERT_TRUE(level.lights[5].spot);
    // Each light's foot, and one point 2 m beside the spotlight's foot: outside its 20 degree
    // half-cone at 3 m up (33.7 degrees), where only the other lights' tails reach.
    std::vector<Vec3> probes;
    for (const auto& l : level.lights) probes.push_back({l.position.x, 0, l.position.z});
    probes.push_back(probes.back() + Vec3{2, 0, 0});
    for (std::size_t i = 0; i < probes.size(); ++i) {
        std::ostringstream pose;
        pose << probes[i].x << " 1.65 " << probes[i].z << " 0 -89";
        const Shot s = shoot("falloff.map", pose.str(), "direct-light", "falloff_" + std::to_string(i));
        const Vec3 p = floorPoint(s);
        const double expected = model(level, p), measured = decodeQuarter(centre(s.image));
        // 8-bit gamma steps: ~1.6 % near 1.0; 0.01 for the darkest probe.
        EXPECT_NEAR(measured, expected, 0.03 * expected + 0.01) << "probe " << i << " at (" << p.x << ", " << p.z << ")";
        if (i == 6) EXPECT_LT(measured, 0.05);  // the spotlight does not reach outside its cone
        else EXPECT_GT(measured, 0.2);
    }
}

TEST(LightingRender, WorldspawnMinlightIsTheAmbient) {
    // Far from every light (x = 90 m): the HDR light there is albedo x ambient (AO off).
    const map::Level level = map::loadLevel(kLevels + "falloff.map");
    ASSERT_TRUE(level.lighting.hasMinlight);
    const std::string pose = "90 1.65 -8 0 -89";
    const Shot direct = shoot("falloff.map", pose, "direct-light", "ambient_direct");
    const Shot hdr = shoot("falloff.map", pose, "hdr-light", "ambient_hdr");
    const Shot albedo = shoot("falloff.map", pose, "albedo", "ambient_albedo");
    EXPECT_LT(decodeQuarter(centre(direct.image)), 0.005);
    const double a = std::pow(centre(albedo.image) / 255.0, 2.2);
    ASSERT_GT(a, 0.05);
    const double ambient = decodeQuarter(centre(hdr.image)) / a;
    EXPECT_NEAR(ambient, level.lighting.minlight / map::kQuakeLightUnit, 0.01 + 0.05 * 0.2);  // 40 / 200
}

TEST(LightingRender, FortyLightsOverOneFaceEachLightTheirFoot) {
    const map::Level level = map::loadLevel(kLevels + "many_lights.map");
    ASSERT_EQ(level.lights.size(), 40u);
    // From 12 m above the grid's middle: all 40 feet in view.
    const Shot s = shoot("many_lights.map", "8 12 -8 0 -89", "direct-light", "many", 640, 360);
    // Lit spots: 4-connected regions above 12/255 (0.004 irradiance; the gaps between the discs are 0).
    const int w = s.image.width, h = s.image.height;
    std::vector<int> label(static_cast<std::size_t>(w) * h, 0);
    const auto value = [&](int x, int y) { return int(s.image.rgba[(static_cast<std::size_t>(y) * w + x) * 4]); };
    std::vector<double> peaks;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (value(x, y) <= 12 || label[static_cast<std::size_t>(y) * w + x]) continue;
            const int id = static_cast<int>(peaks.size()) + 1;
            peaks.push_back(0);
            std::vector<std::pair<int, int>> stack{{x, y}};
            label[static_cast<std::size_t>(y) * w + x] = id;
            while (!stack.empty()) {
                const auto [px, py] = stack.back();
                stack.pop_back();
                peaks.back() = std::max(peaks.back(), decodeQuarter(value(px, py)));
                for (const auto [nx, ny] : {std::pair{px + 1, py}, std::pair{px - 1, py}, std::pair{px, py + 1}, std::pair{px, py - 1}}) {
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h || value(nx, ny) <= 12) continue;
                    int& l = label[static_cast<std::size_t>(ny) * w + nx];
                    if (!l) {
                        l = id;
                        stack.push_back({nx, ny});
                    }
                }
            }
        }
    EXPECT_EQ(peaks.size(), 40u);  // the old 8-light cap lit 8 of them
    // The model at each foot: (28 - 8) / 200, one light alone there.
    const auto& first = level.lights.front();
    EXPECT_NEAR(map::lightAt(first, {first.position.x, 0, first.position.z}, {0, 1, 0}), 0.1, 1e-9);
    // What the frame draws is the bake's lightmap (engine_ext/lightbake, the game's own settings):
    // each spot's brightest pixel is the brightest its bilinear lightmap gets near the foot (the
    // 0.25 m texels round a 1.75 m spot's peak down, 0.084 to 0.1 here). Compared sorted: every
    // light drawn, none twice.
    const lightbake::LightBake bake = lightbake::bakeLevel(level, lightbake::bakeSkyOf(level), {});
    std::vector<double> expected;
    for (const auto& l : level.lights) {
        double best = 0;
        for (double dz = -0.3; dz <= 0.3; dz += 0.02)
            for (double dx = -0.3; dx <= 0.3; dx += 0.02) {
                const Vec3 p{l.position.x + dx, 0, l.position.z + dz};
                const long c = lightbake::chartAt(bake, level, p, {0, 1, 0});
                if (c < 0) continue;
                float d[4], ind[3];
                lightbake::sampleLightmap(bake, static_cast<std::size_t>(c), p, d, ind);
                best = std::max(best, 0.2126 * d[0] + 0.7152 * d[1] + 0.0722 * d[2]);
            }
        expected.push_back(best);
    }
    std::sort(peaks.begin(), peaks.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_GT(expected.front(), 0.07);
    for (std::size_t i = 0; i < std::min(peaks.size(), expected.size()); ++i)
        EXPECT_NEAR(peaks[i], expected[i], 0.006) << "spot " << i;
}

TEST(LightingRender, EnvAmbientScalesTheAmbientInsideItsBoxOnly) {
    // The floor's west half lies under an env_ambient (ambient 0.25, from the floor's top up): its
    // HDR light is albedo x 0.25 x the level's ambient; the east half keeps all of it. Looking
    // straight down 2 m either side of the box's face (x = 16 m) and 6 m inside / outside.
    const map::Level level = map::loadLevel(kLevels + "ambient_area.map");
    ASSERT_EQ(level.ambientAreas.size(), 1u);
    const double full = level.lighting.minlight / map::kQuakeLightUnit;  // 0.2
    const auto ambientAt = [&](const std::string& x, const std::string& name) {
        const std::string pose = x + " 1.65 -8 0 -89";
        const double a = std::pow(centre(shoot("ambient_area.map", pose, "albedo", name + "_albedo").image) / 255.0, 2.2);
        EXPECT_GT(a, 0.05);
        return decodeQuarter(centre(shoot("ambient_area.map", pose, "hdr-light", name + "_hdr").image)) / a;
    };
    EXPECT_NEAR(ambientAt("10", "inside"), 0.25 * full, 0.01);
    EXPECT_NEAR(ambientAt("14", "inside_near"), 0.25 * full, 0.01);
    EXPECT_NEAR(ambientAt("18", "outside_near"), full, 0.01 + 0.05 * full);
    EXPECT_NEAR(ambientAt("22", "outside"), full, 0.01 + 0.05 * full);
}
