// trigger_hurt and trigger_changelevel (sim/triggers.h): `dmg` at most once a second while the
// player stands in it, a death that respawns at the start; a changelevel touched once gives one
// ChangeLevel event naming it and fires its target.
#include "sim_test_levels.h"

#include <gtest/gtest.h>

using namespace obscura;
using namespace obscura::sim;
using namespace obscura::sim::testlevels;

TEST(TriggerHurt, TakesItsDamageOnceASecondAndADeathRespawns) {
    map::Level l = floorLevel();
    addEntity(l, "trigger_hurt", {{"dmg", "10"}}, {{{-1, 0, -1}, {1, 2, 1}}});
    Simulation s(l, startAt({0, 0, 0}));
    s.step({});
    EXPECT_EQ(s.player().health, 90);
    run(s, {}, 59);
    EXPECT_EQ(s.player().health, 90);  // off for a second (60 ticks)
    s.step({});
    EXPECT_EQ(s.player().health, 80);
    // 8 more seconds take it to 0: the player respawns at the start, whole, and is hurt again there.
    run(s, {}, 8 * 60);
    EXPECT_EQ(s.deaths(), 1);
    EXPECT_GT(s.player().health, 80);
}

TEST(TriggerChangelevel, TouchedOnceItNamesItselfOnceAndFiresItsTarget) {
    map::Level l = floorLevel();
    const int changelevel = addEntity(l, "trigger_changelevel", {{"map", "e1m2"}, {"target", "relay"}}, {{{-1, 0, -1}, {1, 2, 1}}});
    const int relay = addEntity(l, "trigger_relay", {{"targetname", "relay"}, {"message", "Leaving"}}, {});
    Simulation s(l, startAt({0, 0, 0}));
    int changes = 0, messages = 0;
    for (int t = 0; t < 120; ++t) {
        s.step({});
        for (const SimEvent& e : s.events()) {
            if (e.type == SimEventType::ChangeLevel) {
                EXPECT_EQ(e.id, changelevel);
                ++changes;
            }
            if (e.type == SimEventType::Message) {
                EXPECT_EQ(e.id, relay);
                ++messages;
            }
        }
    }
    EXPECT_EQ(changes, 1);
    EXPECT_EQ(messages, 1);
}
