// The smoke's shadow towards point lamps (computeLampTransmittance, exportLampTransmittance):
// the plane sweep against an independent ray march of the same density (opticalDepth), walls
// between a lamp and the air, a lamp hung inside its ceiling, the packed export.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "smoke_test_levels.h"

using namespace obscura;
using namespace obscura::smoke;

namespace {

struct SweepError {
    double meanAbsT = 0, worstAbsT = 0;  // |T_sweep - exp(-sigma * opticalDepth)| over the cells compared
    double offCells = 0;                 // the fraction of them off by more than 0.1
    double unshadowed = 0;               // the baseline: mean |1 - exp(-sigma * opticalDepth)|, the lamp not shadowed
    std::size_t cells = 0;
};

// Every free cell above the floor against exp(-shadowSigma * opticalDepth(centre, lamp)):
// opticalDepth marches the trilinear density in half cells, a different integrator from the sweep.
SweepError compare(const SmokeVolume& vol, const Vec3& lamp) {
    std::vector<float> T;
    vol.computeLampTransmittance(lamp, T);
    const GridInfo& g = vol.grid();
    const double sigma = vol.settings().shadowSigma;
    SweepError e;
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const Vec3 c = g.cellCentre(i, j, k);
                if (vol.voxelSolidAt(i, j, k) || c.y < 0.2) continue;
                const double tau = sigma * vol.opticalDepth(c, lamp);
                const double d = std::fabs(T[g.index(i, j, k)] - std::exp(-tau));
                e.meanAbsT += d;
                e.worstAbsT = std::max(e.worstAbsT, d);
                e.offCells += d > 0.1;
                e.unshadowed += 1 - std::exp(-tau);
                ++e.cells;
            }
    e.meanAbsT /= e.cells;
    e.offCells /= e.cells;
    e.unshadowed /= e.cells;
    return e;
}

float at(const SmokeVolume& vol, const std::vector<float>& T, const Vec3& p) {
    const GridInfo& g = vol.grid();
    const Vec3 c = g.toCellCoords(p);
    return T[g.index(static_cast<int>(std::lround(c.x)), static_cast<int>(std::lround(c.y)),
                     static_cast<int>(std::lround(c.z)))];
}

}  // namespace

// A grown cloud on an open floor, lamps inside the grid beside the cloud, outside it to one side,
// and high above: the sweep agrees with a march of the same density cell by cell, ten times
// closer than no shadow at all. Its error is the bilinear step's blur of the shadow's edge (about
// 2 cells across 30 planes): worst just outside the cloud's silhouette, where the sweep is darker
// (a lamp 5 m off the grid's side: 7% of the cells off by more than 0.1, mean 0.024).
TEST(SmokeLamp, SweepMatchesAMarchOfTheDensity) {
    SmokeVolume vol = SmokeVolume::create(testlevels::openFloor(), {}, {0, 0.1, 0}, testlevels::small(32));
    for (int i = 0; i < 75; ++i) vol.step(1.0 / 30);
    const Vec3 lamps[] = {{2.5, 1.5, 0.7}, {-1.0, 0.6, 1.2}, {9.0, 1.2, -2.0}, {0.3, 12.0, 0.4}};
    for (const Vec3& lamp : lamps) {
        const SweepError e = compare(vol, lamp);
        std::cout << "lamp " << lamp.x << " " << lamp.y << " " << lamp.z << ": " << e.cells << " cells, |dT| mean "
                  << e.meanAbsT << " (unshadowed " << e.unshadowed << "), worst " << e.worstAbsT << ", "
                  << 100 * e.offCells << "% off by > 0.1\n";
        EXPECT_GT(e.unshadowed, 0.1) << "the cloud is between the lamp and many cells";
        EXPECT_LT(e.meanAbsT, 0.03);
        EXPECT_LT(e.meanAbsT, e.unshadowed / 10);
        EXPECT_LT(e.offCells, 0.1);
    }
}

// A wall between the lamp and half the grid: no light behind it with or without smoke, full light
// in front of it while there is no smoke.
TEST(SmokeLamp, WallsBlockTheLamp) {
    map::Level l;
    l.brushes.push_back(testlevels::box({-6, -0.25, -6}, {6, 0, 6}));
    l.brushes.push_back(testlevels::box({0.5, 0, -6}, {0.75, 4, 6}));  // a wall across x = 0.6
    testlevels::finish(l);
    SmokeVolume vol = SmokeVolume::create(l, {}, {-1, 0.1, 0}, testlevels::small(24));
    std::vector<float> T;
    vol.computeLampTransmittance({-2.0, 1.5, 0}, T);
    EXPECT_LT(at(vol, T, {1.5, 1.0, 0}), 1e-3f) << "behind the wall";
    EXPECT_LT(at(vol, T, {1.5, 0.3, 2.0}), 1e-3f) << "behind the wall, off its axis";
    EXPECT_GT(at(vol, T, {-0.5, 1.0, 1.5}), 0.999f) << "in front of it, no smoke yet";
    EXPECT_GT(at(vol, T, {-3.5, 0.5, -2.0}), 0.999f) << "behind the lamp, no smoke yet";
    for (int i = 0; i < 45; ++i) vol.step(1.0 / 30);
    vol.computeLampTransmittance({-2.0, 1.5, 0}, T);
    EXPECT_LT(at(vol, T, {1.5, 1.0, 0}), 1e-3f) << "behind the wall with smoke";
    EXPECT_LT(at(vol, T, {-1.0, 0.3, 0}), 0.9f) << "in the cloud's heart, lit through the cloud";
}

// A lamp set into its ceiling (its centre a few cm inside the brush, as a fixture's light often
// is) still lights the room below; one a metre above the ceiling does not.
TEST(SmokeLamp, ALampInItsCeilingLightsTheRoom) {
    const map::Level room = testlevels::closedRoom({-3, 0, -3}, {3, 2.5, 3});
    SmokeVolume vol = SmokeVolume::create(room, {}, {0, 0.1, 0}, testlevels::small(24));
    std::vector<float> T;
    vol.computeLampTransmittance({0.1, 2.55, -0.2}, T);
    for (const Vec3& p : {Vec3{0, 0.5, 0}, Vec3{1.2, 1.8, 0.4}, Vec3{-1.0, 1.0, -1.3}, Vec3{0.6, 2.2, -0.1}})
        EXPECT_GT(at(vol, T, p), 0.99f) << "below the lamp at " << p.x << " " << p.y << " " << p.z;
    vol.computeLampTransmittance({0.1, 3.6, -0.2}, T);
    EXPECT_LT(at(vol, T, {0, 0.5, 0}), 1e-3f) << "a lamp above the roof";
    EXPECT_LT(at(vol, T, {1.2, 1.8, 0.4}), 1e-3f) << "a lamp above the roof";
}

// The packed export: the lamps' channels in order, unused channels 1, a free cell's value its own.
TEST(SmokeLamp, ExportPacksUpToFourLamps) {
    SmokeVolume vol = SmokeVolume::create(testlevels::standardRoom(), {}, {0, 0.1, 0}, testlevels::small(24));
    for (int i = 0; i < 45; ++i) vol.step(1.0 / 30);
    const std::vector<Vec3> lamps = {{1.5, 2.0, 1.0}, {-1.8, 0.6, -1.0}};
    std::vector<float> rgba, T0, T1;
    vol.exportLampTransmittance(lamps, rgba);
    vol.computeLampTransmittance(lamps[0], T0);
    vol.computeLampTransmittance(lamps[1], T1);
    const GridInfo& g = vol.grid();
    ASSERT_EQ(rgba.size(), 4 * g.cells());
    std::size_t shadowed = 0;
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const std::size_t c = g.index(i, j, k);
                EXPECT_EQ(rgba[4 * c + 2], 1.f);
                EXPECT_EQ(rgba[4 * c + 3], 1.f);
                if (vol.voxelSolidAt(i, j, k)) continue;
                EXPECT_EQ(rgba[4 * c + 0], T0[c]);
                EXPECT_EQ(rgba[4 * c + 1], T1[c]);
                shadowed += T0[c] < 0.5f;
            }
    EXPECT_GT(shadowed, 20u) << "the cloud shadows some air from the first lamp";
    std::vector<float> none;
    vol.exportLampTransmittance({}, none);
    ASSERT_EQ(none.size(), 4 * g.cells());
    for (float v : none) ASSERT_EQ(v, 1.f);
}
