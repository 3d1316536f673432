// The game's signs (game/game_signs.h) on tests/signs/levels/sign_room.map: a shot whose ray
// crosses the plate before its impact opens a hole where it crosses, one whose impact comes first
// (a wall between) does not, and the same events give the same holes.
#include <gtest/gtest.h>

#include "game_signs.h"
#include "map/map_compile.h"
#include "signs/signs_shared.h"

#include <filesystem>

using namespace obscura;
namespace fs = std::filesystem;

namespace {
GameSigns roomSigns() {
    const map::Level level = map::loadLevel((fs::path(OBSCURA_SOURCE_DIR) / "tests/signs/levels/sign_room.map").string());
    return GameSigns(level, {OBSCURA_SIGN_FONT_DIR});
}

// A shot from `eye` at `target`, and its impact `beyond` metres past the target.
std::vector<sim::SimEvent> shotAt(const Vec3& eye, const Vec3& target, double beyond) {
    const Vec3 dir = normalize(target - eye);
    sim::SimEvent shot = sim::SimEvent::at(sim::SimEventType::Shot, eye);
    shot.direction = dir;
    sim::SimEvent impact = sim::SimEvent::at(sim::SimEventType::Impact, target + dir * beyond);
    impact.direction = dir;
    return {shot, impact};
}
}  // namespace

TEST(GameSigns, AShotThroughThePlateOpensAHoleWhereItCrosses) {
    GameSigns signs = roomSigns();
    ASSERT_EQ(signs.specs().size(), 1u);
    const signs::SignSpec& s = signs.specs()[0];
    const Vec3 target = s.centre + s.right * 0.2 + s.up * 0.05;
    signs.onTick(shotAt(Vec3{9, 1.65, -4}, target, 8.0));
    ASSERT_EQ(signs.holes()[0].holes().size(), 1u);
    const signs::Hole& h = signs.holes()[0].holes()[0];
    EXPECT_NEAR(h.x, 0.2, 1e-6);
    EXPECT_NEAR(h.y, 0.05, 1e-6);
    EXPECT_DOUBLE_EQ(h.radius, kSignHoleRadius);
    EXPECT_EQ(signs.version(), 1u);
    // The hole lets the lamp through where the mask was closed: a point straight in front of it.
    const double x = h.x, y = h.y;
    const Vec3 onPlate = s.centre + s.right * x + s.up * y;
    const Vec3 ahead = onPlate + (onPlate - s.lamp) * 2.0;
    EXPECT_GT(signs::throughSign(s, signs.masks()[0], signs.holes()[0].holes(), ahead), 0.9);
    EXPECT_LT(signs::throughSign(s, signs.masks()[0], {}, ahead), 0.1) << "the test point should be behind a closed part of the plate";
}

TEST(GameSigns, AShotStoppedBeforeThePlateOrMissingItMakesNoHole) {
    GameSigns signs = roomSigns();
    const signs::SignSpec& s = signs.specs()[0];
    signs.onTick(shotAt(Vec3{9, 1.65, -4}, s.centre, -1.0));            // its impact 1 m short of the plate
    signs.onTick(shotAt(Vec3{9, 1.65, -4}, s.centre + s.up * 2.0, 5.0));  // over the plate
    EXPECT_TRUE(signs.holes()[0].holes().empty());
    EXPECT_EQ(signs.version(), 0u);
}

TEST(GameSigns, TheSameEventsGiveTheSameHoles) {
    GameSigns a = roomSigns(), b = roomSigns();
    const signs::SignSpec& s = a.specs()[0];
    for (int i = 0; i < 20; ++i) {
        const auto events = shotAt(Vec3{9, 1.65, -4 + 0.01 * i}, s.centre + s.right * (0.03 * i - 0.3), 8.0);
        a.onTick(events);
        b.onTick(events);
    }
    ASSERT_EQ(a.holes()[0].holes().size(), static_cast<std::size_t>(SIGN_MAX_HOLES));  // capped, oldest dropped
    for (std::size_t i = 0; i < a.holes()[0].holes().size(); ++i) {
        EXPECT_EQ(a.holes()[0].holes()[i].x, b.holes()[0].holes()[i].x);
        EXPECT_EQ(a.holes()[0].holes()[i].y, b.holes()[0].holes()[i].y);
    }
}
