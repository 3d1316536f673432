// The one frame loop every run mode goes through (live play, headless runs, replays, timedemos):
// poll the window's events, handle the UI actions they triggered, run this frame's fixed ticks,
// show the result. A RunDriver decides what differs between the modes: how many ticks a frame
// runs (wall clock, or exactly one), when the run ends, and what happens around each frame
// (replay inputs before it, captures and hashes after it). Ctrl-C and SIGTERM (stop_signal.h)
// end any mode at the next frame.
#pragma once

#include "core/fixed_step.h"

#include <chrono>
#include <cstdint>

namespace obscura {

// What the loop drives: the game (app/game_app.h).
class FrameHost {
public:
    virtual ~FrameHost() = default;
    virtual void pollEvents() = 0;       // window events -> input (edges latched there)
    virtual void handleActions() = 0;    // UI actions triggered since the last frame (menu, AO, F12...)
    virtual void tick() = 0;             // one simulation tick
    // The view between the previous and the latest tick (alpha 0..1), rendered; frameMs is what
    // the HUD shows as the frame time.
    virtual void present(double alpha, double frameMs) = 0;
    // A frame nobody looks at: the view follows the state as present() would (camera, props,
    // movers, the HUD's frame-time graph) but nothing is drawn.
    virtual void skipDraw(double alpha, double frameMs) = 0;
    virtual bool paused() const = 0;          // the pause menu is open
    virtual bool interfaceOpen() const = 0;   // the menu or the debug panel: ImGui reads their input in a drawn frame
    virtual bool quitRequested() const = 0;   // the menu's Quit, the window closed
    virtual std::uint64_t simTick() const = 0;
};

// One frame's plan.
struct FramePlan {
    int ticks = 1;
    double alpha = 1.0;
    double frameMs = 0;
    bool draw = true;  // false: skipDraw() instead of present() (a replay's frame that no capture reads)
};

class RunDriver {
public:
    virtual ~RunDriver() = default;
    virtual void beforeFrame(FrameHost&) {}
    virtual FramePlan plan(const FrameHost& host) = 0;
    virtual void afterFrame(FrameHost&) {}
    virtual bool finished(const FrameHost& host) const = 0;
    virtual int exitCode() const { return 0; }
};

// Runs frames until the driver is finished, the game quits or a stop signal arrives; returns the
// driver's exit code.
int runFrames(FrameHost& host, RunDriver& driver);

// A windowed game: ticks follow the wall clock (a leftover-time accumulator), the view
// interpolates between ticks; the pause menu pauses the game. Ends at `maxTicks` (0: never).
class LiveDriver : public RunDriver {
public:
    LiveDriver(double tickRate, long maxTicks);
    FramePlan plan(const FrameHost& host) override;
    bool finished(const FrameHost& host) const override;

private:
    FixedStepClock clock_;
    std::chrono::steady_clock::time_point last_;
    long maxTicks_;
};

// Headless: exactly one tick per rendered frame, no wall clock involved (deterministic); the
// HUD shows the fixed tick time. Ends at `maxTicks` (0: never).
class HeadlessDriver : public RunDriver {
public:
    HeadlessDriver(double tickRate, long maxTicks) : frameMs_(1000.0 / tickRate), maxTicks_(maxTicks) {}
    FramePlan plan(const FrameHost&) override { return {1, 1.0, frameMs_}; }
    bool finished(const FrameHost& host) const override;

private:
    double frameMs_;
    long maxTicks_;
};

}  // namespace obscura
