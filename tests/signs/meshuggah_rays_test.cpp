// The Meshuggah mode's rays (engine_ext/signs/meshuggah_rays.h): through the coarse 8-bit mask, from
// the lamp, on the plate's plane, to the range, at most kMaxRays; holes add rays, a long text
// coarsens the grid.
#include <gtest/gtest.h>

#include "signs/meshuggah_rays.h"
#include "signs/sign_light.h"

#include <cmath>

using namespace obscura;
using namespace obscura::signs;

namespace {
SignSpec testSign(const std::string& text) {
    SignSpec s;
    s.where = "test";
    s.text = text;
    s.fontFile = OBSCURA_SIGN_FONT;
    s.centre = {0, 0, 0};
    s.lamp = {0.1, 0.05, -0.3};  // off the centre: the rays diverge unevenly
    s.range = 10;
    return s;
}
}  // namespace

TEST(MeshuggahRays, FromTheLampThroughTheLettersToTheRange) {
    const SignSpec s = testSign("EXIT");
    const SignMask m = bakeMask(s, maxPenumbraRadius(s) + 0.02, 32);
    double spacing = 0;
    const auto rays = meshuggahRays(s, m, {}, spacing);
    EXPECT_DOUBLE_EQ(spacing, s.letterHeight / 32);
    ASSERT_GT(rays.size(), 100u);
    EXPECT_LE(rays.size(), kMaxRays);
    std::size_t full = 0;
    for (const auto& r : rays) {
        EXPECT_NEAR(length(r.direction), 1, 1e-12);
        // From the lamp: the start lies on the lamp's ray, kStartOffset past the plane.
        const Vec3 fromLamp = r.start - s.lamp;
        EXPECT_NEAR(length(fromLamp - r.direction * length(fromLamp)), 0, 1e-9);
        EXPECT_NEAR(dot(r.start - s.centre, s.facing), kStartOffset * dot(r.direction, s.facing), 1e-9);
        EXPECT_NEAR(length(fromLamp) + r.length, s.range, 1e-9);
        // Through a letter, or within a texel of one (the 8-bit edge).
        const Vec3 q = r.start - r.direction * kStartOffset;
        const double x = dot(q - s.centre, s.right), y = dot(q - s.centre, s.up);
        EXPECT_GT(m.at(x, y), -0.5 * spacing - 1e-9);
        EXPECT_GE(r.coverage, 1);
        if (m.at(x, y) > spacing) {
            EXPECT_EQ(r.coverage, 255);  // deep inside (the cone is wide open this near the axis)
            ++full;
        }
    }
    EXPECT_GT(full, rays.size() / 4);
}

TEST(MeshuggahRays, AHoleAddsRaysAndALongTextCoarsens) {
    const SignSpec s = testSign("EXIT");
    const SignMask m = bakeMask(s, maxPenumbraRadius(s) + 0.02, 32);
    double spacing = 0;
    const auto plain = meshuggahRays(s, m, {}, spacing);
    // A 3 cm hole in the margin under the letters: ~ pi 0.03^2 / spacing^2 = 23 more rays.
    const auto holed = meshuggahRays(s, m, {{0, -m.halfHeight + 0.04, 0.03}}, spacing);
    EXPECT_GT(holed.size(), plain.size() + 15);
    EXPECT_LT(holed.size(), plain.size() + 35);

    SignSpec big = testSign("EMERGENCY EXIT THIS WAY");
    big.letterHeight = 1;
    big.lamp = {0, 0, -4};  // far enough behind that the cone opens over the whole plate
    big.coneDegrees = 89;
    const SignMask bm = bakeMask(big, maxPenumbraRadius(big) + 0.02, 16);
    const auto rays = meshuggahRays(big, bm, {}, spacing);
    EXPECT_LE(rays.size(), kMaxRays);
    EXPECT_GT(rays.size(), kMaxRays / 2);
    EXPECT_GT(spacing, big.letterHeight / 32);
}
