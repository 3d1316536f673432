// The lamps' light on the smoke's grid (lampLight, smoke_lamp_light.h): what the march's former
// per-sample loop summed, at the cells' centres: one lamp exactly, its shadow, the occupied box's
// reach, the mean direction of lamps on opposite sides.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "smoke/smoke_lamp_light.h"

using namespace obscura;
using namespace obscura::smoke;

namespace {

GridInfo grid8() {
    GridInfo g;
    g.origin = {0, 0, 0};
    g.nx = g.ny = g.nz = 8;
    g.cellSize = 0.5;
    return g;
}

const SmokeBox kWhole{{0, 0, 0}, {4, 4, 4}};

struct Texels {
    float a[4], b[4];
};

Texels at(const GridInfo& g, const std::vector<float>& out, int i, int j, int k) {
    const std::size_t c = g.index(i, j, k), n = g.cells();
    Texels t;
    for (int q = 0; q < 4; ++q) {
        t.a[q] = out[4 * c + q];
        t.b[q] = out[4 * n + 4 * c + q];
    }
    return t;
}

}  // namespace

TEST(SmokeLampLight, OneUnshadowedLampIsExactAtACellsCentre) {
    const GridInfo g = grid8();
    const SmokeLamp lamp{{3.1, 2.2, 0.9}, {2.0, 1.0, 0.5}, 6.0};
    std::vector<float> out;
    lampLight(g, kWhole, {lamp}, 0, {}, out);
    ASSERT_EQ(out.size(), 8 * g.cells());
    const Vec3 p = g.cellCentre(1, 2, 6);
    const Vec3 toLamp = lamp.position - p;
    const double d = length(toLamp), f = 1 - d / lamp.range;
    const Texels t = at(g, out, 1, 2, 6);
    const double scale = f * f * (1 + kLampMultipleWeight);
    EXPECT_NEAR(t.a[0], 2.0 * scale, 1e-5);
    EXPECT_NEAR(t.a[1], 1.0 * scale, 1e-5);
    EXPECT_NEAR(t.a[2], 0.5 * scale, 1e-5);
    EXPECT_NEAR(t.a[3], 1 / (1 + kLampMultipleWeight), 1e-6);  // the single share
    for (int q = 0; q < 3; ++q) EXPECT_NEAR(t.b[q], toLamp[q] / d, 1e-6);  // the way to the lamp, unit length
}

TEST(SmokeLampLight, AShadowedLampsSingleTermTakesTAndItsOctaveTheRoot) {
    const GridInfo g = grid8();
    const SmokeLamp lamp{{2, 2, 2}, {1, 1, 1}, 8.0};
    std::vector<float> lit, shadowed;
    const std::vector<float> T(4 * g.cells(), 0.25f);
    lampLight(g, kWhole, {lamp}, 0, T, lit);       // no channel for it: not shadowed
    lampLight(g, kWhole, {lamp}, 1, T, shadowed);  // channel 0: T = 0.25
    const Texels a = at(g, lit, 6, 1, 3), b = at(g, shadowed, 6, 1, 3);
    const double base = a.a[0] / (1 + kLampMultipleWeight);  // f^2
    EXPECT_NEAR(b.a[0], base * (0.25 + kLampMultipleWeight * 0.5), 1e-5);
    EXPECT_NEAR(b.a[3], 0.25 / (0.25 + kLampMultipleWeight * 0.5), 1e-5);
}

TEST(SmokeLampLight, NothingOutsideTheBoxsReachOrTheLampsRange) {
    const GridInfo g = grid8();
    const SmokeBox corner{{0, 0, 0}, {1, 1, 1}};  // cells 0..1; their trilinear reach: up to cell 3
    std::vector<float> out;
    lampLight(g, corner, {{{0.5, 0.5, 0.5}, {1, 1, 1}, 2.0}}, 0, {}, out);
    EXPECT_GT(at(g, out, 1, 1, 1).a[0], 0.f);
    EXPECT_GT(at(g, out, 3, 0, 0).a[0], 0.f);
    EXPECT_EQ(at(g, out, 4, 0, 0).a[0], 0.f);        // past the box's reach
    EXPECT_EQ(at(g, out, 3, 3, 3).a[0], 0.f);        // 2.17 m away: out of the 2 m range
    std::vector<float> none;
    lampLight(g, kWhole, {}, 0, {}, none);
    for (float v : none) ASSERT_EQ(v, 0.f);
}

TEST(SmokeLampLight, EqualLampsOnOppositeSidesLeaveNoDirection) {
    const GridInfo g = grid8();
    const Vec3 c = g.cellCentre(4, 4, 4);
    std::vector<float> out;
    lampLight(g, kWhole, {{c + Vec3{1.5, 0, 0}, {1, 1, 1}, 5}, {c - Vec3{1.5, 0, 0}, {1, 1, 1}, 5}}, 0, {}, out);
    const Texels t = at(g, out, 4, 4, 4);
    EXPECT_NEAR(std::hypot(t.b[0], t.b[1], t.b[2]), 0.0, 1e-6);  // the march's phase: isotropic here
    const Texels side = at(g, out, 6, 4, 4);                      // nearer the +x lamp
    EXPECT_GT(side.b[0], 0.2f);
    EXPECT_LT(side.b[0], 1.0f);
}
