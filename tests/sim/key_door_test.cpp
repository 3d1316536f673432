// Key doors (sim/pickups.h, sim/movers.h): a silver-key door says so when touched without the key
// (once in 2 s), the key is taken by touch, and the door then opens, uses the key up and stays open.
#include "sim_test_levels.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace obscura;
using namespace obscura::sim;
using namespace obscura::sim::testlevels;

namespace {
std::vector<Notice> notices(const Simulation& s) {
    std::vector<Notice> out;
    for (const SimEvent& e : s.events())
        if (e.type == SimEventType::Message && e.notice != Notice::None) out.push_back(e.notice);
    return out;
}

// A silver-key door across z = -5 (the player walks -Z into it); the key, if any, on the way.
map::Level keyLevel(bool withKey) {
    map::Level l = floorLevel();
    addEntity(l, "func_door", {{"angle", "-1"}, {"spawnflags", "16"}}, {{{-1, 0, -5.125}, {1, 2.5, -4.875}}});
    if (withKey) {
        map::LevelEntity key;
        key.classname = "item_key1";
        key.keys = {{"classname", "item_key1"}};
        key.hasOrigin = true;
        key.origin = {0, 0.75, -2};
        l.entities.push_back(key);
    }
    return l;
}
}  // namespace

TEST(KeyDoor, WithoutTheKeyItSaysSoAndStaysShut) {
    Simulation s(keyLevel(false), startAt({0, 0, -3}));
    int told = 0;
    for (int t = 0; t < 5 * 60; ++t) {  // walking into it for 5 s
        s.step(walk());
        for (Notice n : notices(s)) {
            EXPECT_EQ(n, Notice::NeedSilverKey);
            ++told;
        }
    }
    EXPECT_EQ(told, 3);  // at once, then every 2 s
    EXPECT_EQ(s.movers().offset(0), Vec3{});
    EXPECT_EQ(noticeText(Notice::NeedSilverKey, 0), "You need the silver key");
    EXPECT_EQ(noticeText(Notice::NeedGoldKey, 2), "You need the gold keycard");
}

TEST(KeyDoor, TheKeyIsTakenByTouchAndTheDoorUsesItUp) {
    Simulation s(keyLevel(true), startAt({0, 0, -0.5}));
    std::vector<Notice> all;
    for (int t = 0; t < 3 * 60; ++t) {
        s.step(walk());
        for (Notice n : notices(s)) all.push_back(n);
    }
    ASSERT_FALSE(all.empty());
    EXPECT_EQ(all.front(), Notice::GotSilverKey);
    EXPECT_EQ(std::count(all.begin(), all.end(), Notice::NeedSilverKey), 0);
    EXPECT_FALSE(s.pickups().holds(kSilverKey));  // used up
    EXPECT_GT(s.movers().offset(0).y, 0);          // rising (angle -1)
    run(s, {}, 600);
    EXPECT_GT(s.movers().offset(0).y, 2.0);  // stays open
}
