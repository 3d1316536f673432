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
        // An open menu or panel is drawn whatever the plan: ImGui takes their input in a drawn frame.
        if (plan.draw || host.interfaceOpen()) host.present(plan.alpha, plan.frameMs);
        else host.skipDraw(plan.alpha, plan.frameMs);
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
    int ticks = clock_.advance(frameSeconds);
    if (host.paused()) return {0, 1.0, frameSeconds * 1000.0};
    double alpha = clock_.alpha();
    // A run of --ticks N stops at exactly N, even when a slow frame banked several ticks: the
    // last frame shows that tick as it is (alpha 1), the state a headless run ends on.
    if (maxTicks_ > 0) {
        const long left = maxTicks_ - static_cast<long>(host.simTick());
        if (ticks >= left) {
            ticks = static_cast<int>(left < 0 ? 0 : left);
            alpha = 1.0;
        }
    }
    return {ticks, alpha, frameSeconds * 1000.0};
}

bool LiveDriver::finished(const FrameHost& host) const {
    return maxTicks_ > 0 && static_cast<long>(host.simTick()) >= maxTicks_;
}

bool HeadlessDriver::finished(const FrameHost& host) const {
    return maxTicks_ > 0 && static_cast<long>(host.simTick()) >= maxTicks_;
}

}  // namespace obscura
