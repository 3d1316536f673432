// SIGINT / SIGTERM only raise the flag the frame loop polls while a StopSignal lives.
#include <gtest/gtest.h>

#include "stop_signal.h"

#include <csignal>

using namespace obscura;

TEST(StopSignal, ASignalRaisesTheFlagAndTheProcessGoesOn) {
    struct sigaction before {};
    sigaction(SIGTERM, nullptr, &before);
    {
        const StopSignal stop;
        EXPECT_FALSE(StopSignal::requested());
        std::raise(SIGTERM);
        EXPECT_TRUE(StopSignal::requested());
        EXPECT_EQ(StopSignal::pending(), SIGTERM);
    }
    struct sigaction after {};
    sigaction(SIGTERM, nullptr, &after);
    EXPECT_EQ(after.sa_handler, before.sa_handler);  // the previous handler is back
    {
        const StopSignal stop;  // a new run starts clear
        EXPECT_FALSE(StopSignal::requested());
        std::raise(SIGINT);
        EXPECT_EQ(StopSignal::pending(), SIGINT);
    }
}
