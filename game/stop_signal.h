// Ctrl-C and SIGTERM end every run (live, headless, --replay, --timedemo) cleanly: while a
// StopSignal lives, SIGINT and SIGTERM only raise a flag that the one frame loop
// (app/run_driver.h) polls each frame, so the run leaves its loop, prints its state hash and
// shuts OGRE down in order. A second signal while the first is pending ends the process at once
// (the default action), so a run stuck outside the loop can still be stopped.
#pragma once

#include <csignal>

namespace obscura {

class StopSignal {
public:
    StopSignal();   // installs the handlers (and clears the flag)
    ~StopSignal();  // restores the previous handlers
    StopSignal(const StopSignal&) = delete;
    StopSignal& operator=(const StopSignal&) = delete;

    // The signal that asked the run to stop, or 0.
    static int pending();
    static bool requested() { return pending() != 0; }

private:
    struct sigaction previousInt_{}, previousTerm_{};
};

}  // namespace obscura
