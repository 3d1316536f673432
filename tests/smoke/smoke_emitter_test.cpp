// The emitter: the gas starts only in cells the canister's own cell reaches through open faces,
// in the same amount wherever the grenade lies, and carries its own density (a volume source,
// diluted by mixing only).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>

#include "smoke_test_levels.h"

using namespace obscura;
using namespace obscura::smoke;

namespace {

// Emitter cells form one set connected through faces between fluid cells, containing the seed.
bool emitterConnected(const SmokeState& s) {
    const std::set<std::size_t> cells(s.emitterList.begin(), s.emitterList.end());
    if (!cells.count(s.startCell)) return false;
    std::set<std::size_t> reached{s.startCell};
    std::vector<std::size_t> stack{s.startCell};
    const std::ptrdiff_t off[6] = {-1, 1, -s.dims.sy, s.dims.sy, -s.dims.sz, s.dims.sz};
    while (!stack.empty()) {
        const std::size_t c = stack.back();
        stack.pop_back();
        for (std::ptrdiff_t o : off) {
            const std::size_t m = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + o);
            if (cells.count(m) && !reached.count(m) && s.staticClass[m] == kFluid) {
                reached.insert(m);
                stack.push_back(m);
            }
        }
    }
    return reached.size() == cells.size();
}

double densityWhere(const SmokeVolume& vol, const std::function<bool(const Vec3&)>& where) {
    const GridInfo& g = vol.grid();
    double sum = 0;
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                if (where(g.cellCentre(i, j, k))) sum += vol.densityAt(i, j, k);
    return sum;
}

}  // namespace

// In the open, on the floor, against each kind of wall, in floor and ceiling corners, stuck to the
// ceiling, at sub-cell offsets: always the same number of emitter cells (what a free sphere of
// emitterRadius holds), the same volume source, the same smoke after one step.
TEST(SmokeEmitter, SameAmountWhereverTheGrenadeLies) {
    const map::Level& room = testlevels::standardRoom();  // 5 x 2.75 x 5 m, closed
    const SmokeSettings st = testlevels::small(24);
    const double h3 = std::pow(st.cellSize, 3);
    const double sphereCells = std::round(4.0 / 3.0 * M_PI * std::pow(st.emitterRadius, 3) / h3);
    const double dt = 0.05;
    const double emitted = st.emitSmokeDensity * st.emitGasRate * dt;  // density x m^3 in one step
    const Vec3 places[] = {
        {0, 1.2, 0},          {0.3, 0.02, -0.2},  {0.13, 0.05, 0.07},  {2.45, 0.02, 0.4},   {-2.47, 0.3, -0.1},
        {0.1, 0.02, -2.45},   {0.6, 1.0, 2.48},   {-2.45, 0.02, -2.45}, {2.47, 0.03, 2.41}, {0.2, 2.73, 0.1},
        {2.45, 2.72, -2.45},  {-2.4, 2.7, 2.4},   {-1.1, 0.01, 1.9},
    };
    for (const Vec3& at : places) {
        SCOPED_TRACE(testing::Message() << "grenade at " << at.x << " " << at.y << " " << at.z);
        SmokeVolume vol = SmokeVolume::create(room, {}, at, st);
        const SmokeState& s = vol.state();
        EXPECT_EQ(static_cast<double>(s.emitterCells), sphereCells);
        EXPECT_NEAR(s.emitterRate * s.emitterCells * h3, st.emitGasRate, 1e-5 * st.emitGasRate) << "the gas's volume rate";
        EXPECT_TRUE(emitterConnected(s)) << "the gas reaches every emitter cell from the canister's cell";
        double farthest = 0;
        for (std::size_t c : s.emitterList) {
            const int i = static_cast<int>(c % s.grid.nx), j = static_cast<int>((c / s.grid.nx) % s.grid.ny),
                      k = static_cast<int>(c / (static_cast<std::size_t>(s.grid.nx) * s.grid.ny));
            farthest = std::max(farthest, length(s.grid.cellCentre(i, j, k) - s.emitterCentre));
        }
        EXPECT_LE(farthest, 3.0 * st.emitterRadius);
        vol.step(dt);
        EXPECT_NEAR(vol.totalDensity(), emitted, 1e-5 * emitted) << "the smoke of one step's gas, all of it in the room";
    }
}

// The case: a grenade resting against a 0.1 m wall whose far face is 0.13 m from it; the
// real way round is ~7 m, through a doorway at the wall's far end. The old emitter sphere put
// density 1.5 behind the wall after one step and 6.0 after a second.
TEST(SmokeEmitter, NothingBehindAThinWall) {
    map::Level level;
    testlevels::addRoom(level, {-3, 0, -2.5}, {3, 2.75, 2.5}, 0.25);
    level.brushes.push_back(testlevels::box({0.3, 0, -2.5}, {0.4, 2.75, 1.5}));  // doorway at z in [1.5, 2.5]
    testlevels::finish(level);
    SmokeVolume vol = SmokeVolume::create(level, {}, {0.27, 0.02, -2.0}, testlevels::small(32));
    auto behind = [&](const Vec3& p) { return p.x > 0.4 && p.z < 1.0; };  // beyond the wall, away from the door
    vol.step(0.05);
    EXPECT_GT(vol.totalDensity(), 0.0);
    EXPECT_EQ(densityWhere(vol, behind), 0.0) << "after one step";
    float worst = 0;
    for (int i = 0; i < 19; ++i) vol.step(0.05);
    const GridInfo& g = vol.grid();
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                if (behind(g.cellCentre(i, j, k))) worst = std::max(worst, vol.densityAt(i, j, k));
    const double mine = densityWhere(vol, [](const Vec3& p) { return p.x < 0.3; });
    std::cout << "after 1 s: densest cell behind the wall " << worst << ", " << densityWhere(vol, behind) << " of "
              << mine << " (cell sums) behind it vs on the grenade's side\n";
    EXPECT_LT(worst, 0.05) << "only what came round through the doorway, thinned";
}

// The gas's density is the cloud's: after the bloom on open floor no cell exceeds the released
// gas's density by more than a few per cent (no multiplication by the expansion), the cloud's
// body stays near it (diluted by mixing at the edges only), and all the smoke released is there.
TEST(SmokeEmitter, CloudDensityIsTheGasDensity) {
    const SmokeSettings st = testlevels::small(40);  // a 10 m box: room for the ~3.2 m dome
    SmokeVolume vol = SmokeVolume::create(testlevels::openFloor(), {}, {0, 0.05, 0}, st);
    float peak = 0;
    while (vol.age() < 2.0) {
        vol.step(0.05);
        for (float d : vol.state().density) peak = std::max(peak, d);
    }
    double mass = 0, weighted = 0;
    for (float d : vol.state().density) {
        mass += d;
        weighted += static_cast<double>(d) * d;
    }
    const double h3 = std::pow(st.cellSize, 3);
    const double released = st.emitSmokeDensity * st.emitGasRate * st.emitTime;
    std::cout << "after 2 s: densest cell ever " << peak << ", mass-weighted mean density " << weighted / mass << ", total "
              << mass * h3 << " of " << released << " released\n";
    EXPECT_LE(peak, 1.05 * st.emitSmokeDensity);
    EXPECT_GT(weighted / mass, 0.7 * st.emitSmokeDensity);
    EXPECT_NEAR(mass * h3, released, 0.02 * released);
}
