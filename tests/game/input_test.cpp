#include <gtest/gtest.h>

#include "input.h"

#include <algorithm>

using namespace obscura;

TEST(Input, BoundKeysBecomeMovementAndEdgeActions) {
    Settings s;
    InputState in(s);
    in.press("w");
    in.press("d");
    in.press("o");
    in.press("o");  // auto-repeat must not trigger twice
    auto c = in.takeCommand();
    EXPECT_FLOAT_EQ(c.forward, 1.0f);
    EXPECT_FLOAT_EQ(c.right, 1.0f);
    const auto t = in.takeTriggered();  // every press is an edge: forward, right, cycle_ao
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(std::count(t.begin(), t.end(), Action::CycleAo), 1);
    EXPECT_TRUE(t[0] == Action::Forward);
    EXPECT_TRUE(in.takeTriggered().empty());
    in.release("w");
    in.press("s");
    EXPECT_FLOAT_EQ(in.takeCommand().forward, -1.0f);
}

TEST(Input, RebindingMovesTheAction) {
    Settings s;
    s.bindings[Action::Jump] = "j";
    InputState in(s);
    in.press("space");
    EXPECT_FALSE(in.takeCommand().jump);
    in.press("j");
    EXPECT_TRUE(in.takeCommand().jump);
}

TEST(Input, MouseMotionIsConsumedOncePerTickAndRespectsInvert) {
    Settings s;
    InputState in(s);
    in.mouseMotion(10, 0);
    in.mouseMotion(10, 5);
    auto c = in.takeCommand();
    EXPECT_LT(c.yawDelta, 0.0f);     // moving right turns right
    EXPECT_LT(c.pitchDelta, 0.0f);   // moving down looks down
    EXPECT_NEAR(c.yawDelta, -20 * 0.022 * 3.14159265 / 180.0, 1e-6);
    EXPECT_FLOAT_EQ(in.takeCommand().yawDelta, 0.0f);
    s.invertMouse = true;
    in.mouseMotion(0, 5);
    EXPECT_GT(in.takeCommand().pitchDelta, 0.0f);
}
