// Fixed simulation tick with a leftover-time accumulator (as Quake III's server frame).
// The wall-clock frame time only decides *how many* ticks run; each tick always advances
// the simulation by exactly `dt`, so the simulation never depends on the frame rate.
#pragma once

#include <algorithm>

namespace obscura {

class FixedStepClock {
public:
    // maxFrame: a frame longer than this (a hitch, a debugger stop) is clamped, so the
    // simulation slows down instead of spiralling into ever more catch-up ticks.
    explicit FixedStepClock(double dt = 1.0 / 60.0, double maxFrame = 0.25) : dt_(dt), maxFrame_(maxFrame) {}

    // Adds a frame's elapsed time; returns how many ticks to run now.
    int advance(double frameSeconds) {
        accumulator_ += std::clamp(frameSeconds, 0.0, maxFrame_);
        int ticks = 0;
        while (accumulator_ >= dt_) {
            accumulator_ -= dt_;
            ++ticks;
        }
        return ticks;
    }

    // How far (0..1) the render time lies between the previous and the latest tick.
    double alpha() const { return accumulator_ / dt_; }
    double dt() const { return dt_; }
    void reset() { accumulator_ = 0.0; }

private:
    double dt_;
    double maxFrame_;
    double accumulator_ = 0.0;
};

}  // namespace obscura
