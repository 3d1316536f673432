// See run_driver.h.
#include "app/run_driver.h"

#include "stop_signal.h"

namespace obscura {

int runFrames(FrameHost& host, RunDriver& driver) {
    while (!StopSignal::requested() && !host.quitRequested() && !driver.finished(host)) {
        driver.beforeFrame(host);
        host.pollEvents();
        const FramePlan plan = driver.plan(host);
        host.handleActions();
        for (int n = plan.ticks; n > 0; --n) host.tick();
        host.present(plan.alpha, plan.frameMs);
        driver.afterFrame(host);
    }
    return driver.exitCode();
}

LiveDriver::LiveDriver(double tickRate, long maxTicks)
    : clock_(1.0 / tickRate), last_(std::chrono::steady_clock::now()), maxTicks_(maxTicks) {}

FramePlan LiveDriver::plan(const FrameHost& host) {
    const auto now = std::chrono::steady_clock::now();
    const double frameSeconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    // The pause menu pauses the game (the clock does not bank the time either).
    const int ticks = clock_.advance(frameSeconds);
    if (host.paused()) return {0, 1.0, frameSeconds * 1000.0};
    return {ticks, clock_.alpha(), frameSeconds * 1000.0};
}

bool LiveDriver::finished(const FrameHost& host) const {
    return maxTicks_ > 0 && static_cast<long>(host.simTick()) >= maxTicks_;
}

bool HeadlessDriver::finished(const FrameHost& host) const {
    return maxTicks_ > 0 && static_cast<long>(host.simTick()) >= maxTicks_;
}

}  // namespace obscura
