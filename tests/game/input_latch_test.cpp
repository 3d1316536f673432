// Input edges are latched on the event, not sampled at the tick: a press and release between two
// ticks still reaches the next tick; Shift is read when O goes down; the menu and the F1 panel take
// the pointer.
#include <gtest/gtest.h>

#include "../sim/sim_test_levels.h"
#include "input.h"

#include <algorithm>

using namespace obscura;

namespace {
int countEvents(const std::vector<sim::SimEvent>& events, sim::SimEventType type) {
    return static_cast<int>(std::count_if(events.begin(), events.end(), [type](const sim::SimEvent& e) { return e.type == type; }));
}
}  // namespace

TEST(InputLatch, APressAndReleaseInsideOneFrameReachTheNextTickOnce) {
    Settings s;
    InputState in(s);
    struct Case {
        const char* key;
        bool sim::PlayerCommand::*field;
    };
    for (const Case c : {Case{"mouse1", &sim::PlayerCommand::fire}, Case{"space", &sim::PlayerCommand::jump},
                         Case{"r", &sim::PlayerCommand::reload}, Case{"lctrl", &sim::PlayerCommand::crouch},
                         Case{"g", &sim::PlayerCommand::throwHeld}}) {
        in.press(c.key);
        in.release(c.key);
        EXPECT_TRUE(in.takeCommand().*c.field) << c.key << ": the tick after the tap sees it";
        EXPECT_FALSE(in.takeCommand().*c.field) << c.key << ": and only that tick";
    }
    // Held across ticks: every tick sees it, until released.
    in.press("mouse1");
    EXPECT_TRUE(in.takeCommand().fire);
    EXPECT_TRUE(in.takeCommand().fire);
    in.release("mouse1");
    EXPECT_FALSE(in.takeCommand().fire);
}

TEST(InputLatch, ReleaseAllForgetsLatchedPresses) {
    Settings s;
    InputState in(s);
    in.press("mouse1");
    in.release("mouse1");
    in.releaseAll();  // the menu opened before the tick
    EXPECT_FALSE(in.takeCommand().fire);
}

TEST(InputLatch, TenInstantClicksFireTenShots) {
    // Each click pressed and released between two ticks (a fast mouse inside one frame).
    Settings s;
    InputState in(s);
    sim::Simulation sim(sim::testlevels::floorLevel(), {});
    int shots = 0;
    for (int click = 0; click < 10; ++click) {
        in.press("mouse1");
        in.release("mouse1");
        for (int t = 0; t < 8; ++t) {  // past the rifle's 0.1 s between rounds
            sim.step(in.takeCommand());
            shots += countEvents(sim.events(), sim::SimEventType::Shot);
        }
    }
    EXPECT_EQ(shots, 10);
}

TEST(InputLatch, AQuickTapJumps) {
    Settings s;
    InputState in(s);
    sim::Simulation sim(sim::testlevels::floorLevel(), {});
    for (int t = 0; t < 10; ++t) sim.step(in.takeCommand());
    ASSERT_TRUE(sim.player().onGround);
    in.press("space");
    in.release("space");
    sim.step(in.takeCommand());
    EXPECT_GT(sim.player().velocity.y, 1.0);
    EXPECT_FALSE(sim.player().onGround);
}

TEST(InputLatch, ShiftIsReadWhenTheKeyGoesDown) {
    Settings s;
    InputState in(s);
    // A quick Shift+O: Shift released again before the tick handles the O.
    in.press("lshift");
    in.press("o");
    in.release("o");
    in.release("lshift");
    auto t = in.takeTriggered();
    auto cycle = std::find(t.begin(), t.end(), Action::CycleAo);
    ASSERT_NE(cycle, t.end());
    EXPECT_TRUE(cycle->shift);
    // O alone, then Shift pressed after it (before the tick): forwards.
    in.press("o");
    in.press("rshift");
    t = in.takeTriggered();
    cycle = std::find(t.begin(), t.end(), Action::CycleAo);
    ASSERT_NE(cycle, t.end());
    EXPECT_FALSE(cycle->shift);
}

TEST(InputRouting, TheMenuAndThePanelTakeThePointerWindowedOnly) {
    InputRouting r;
    EXPECT_FALSE(r.mouseToUi());
    EXPECT_TRUE(r.grabPointer());
    r.panelShown = true;  // F1: clicks go to the panel, motion does not turn the view, keys still play
    EXPECT_TRUE(r.mouseToUi());
    EXPECT_FALSE(r.keysToUi());
    EXPECT_FALSE(r.grabPointer());
    r.panelShown = false;
    r.menuOpen = true;  // Esc: the menu takes pointer and keys
    EXPECT_TRUE(r.mouseToUi());
    EXPECT_TRUE(r.keysToUi());
    EXPECT_FALSE(r.grabPointer());
    r.headless = true;  // replays and headless runs: everything to the game, nothing grabbed
    EXPECT_FALSE(r.mouseToUi());
    EXPECT_FALSE(r.keysToUi());
    EXPECT_FALSE(r.grabPointer());
}
