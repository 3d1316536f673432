// `message` (sim/triggers.h): an entity with a message that uses its targets gives one Message
// event naming it, as Quake's SUB_UseTargets centre-prints it; delayed uses print when they come due.
#include "sim_test_levels.h"

#include <gtest/gtest.h>

#include <vector>

using namespace obscura;
using namespace obscura::sim;
using namespace obscura::sim::testlevels;

namespace {
// The Message events' entity ids over `ticks` ticks of `cmd`, with the tick each came.
std::vector<std::pair<int, int>> messages(Simulation& s, const PlayerCommand& cmd, int ticks) {
    std::vector<std::pair<int, int>> out;
    for (int t = 1; t <= ticks; ++t) {
        s.step(cmd);
        for (const SimEvent& e : s.events())
            if (e.type == SimEventType::Message) out.push_back({t, e.id});
    }
    return out;
}
}  // namespace

TEST(Messages, ATriggerWithAMessageNamesItselfOnceWhenItFires) {
    map::Level l = floorLevel();
    const int once = addEntity(l, "trigger_once", {{"message", "The gate opens"}}, {{{2, 0, -1}, {3, 2, 1}}});
    addEntity(l, "trigger_once", {}, {{{2, 0, -1}, {3, 2, 1}}});  // no message: no event
    Simulation s(l, startAt({0, 0, 0}));
    const auto got = messages(s, walk(0, 1), 120);  // strafe +X through both
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].second, once);
    EXPECT_EQ(l.entities[static_cast<std::size_t>(got[0].second)].value("message"), "The gate opens");
}

TEST(Messages, ARelayWithADelayPrintsWhenItsUseComesDue) {
    map::Level l = floorLevel();
    addEntity(l, "trigger_once", {{"target", "r"}}, {{{-1, 0, -1}, {1, 2, 1}}});
    const int relay = addEntity(l, "trigger_relay", {{"targetname", "r"}, {"delay", "0.5"}, {"message", "Half a second"}}, {});
    Simulation s(l, startAt({0, 0, 0}));
    const auto got = messages(s, {}, 120);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].second, relay);
    EXPECT_NEAR(got[0].first, 1 + 30, 1);  // fired on the first tick, due 30 ticks (0.5 s at 60 Hz) later
}

TEST(Messages, AMultipleTriggerPrintsEachTimeItFires) {
    map::Level l = floorLevel();
    addEntity(l, "trigger_multiple", {{"message", "again"}, {"wait", "1"}}, {{{-1, 0, -1}, {1, 2, 1}}});
    Simulation s(l, startAt({0, 0, 0}));
    const auto got = messages(s, {}, 150);  // standing in it: fires at once, then every second
    ASSERT_EQ(got.size(), 3u);
    EXPECT_EQ(got[1].first - got[0].first, 60);
}
