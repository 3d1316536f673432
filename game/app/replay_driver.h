// Replays and timedemos through the one frame loop (app/run_driver.h): before each frame the
// script's inputs and `set`s due at that tick, exactly one tick per frame, after it the captures
// and state hashes due (a diverging hash names the script line and the tick); a timedemo also
// times every frame and prints the statistics at the end.
//
// No OGRE here: the game (ReplayHost) injects the inputs as real window events, applies settings
// and writes images.
#pragma once

#include "app/run_driver.h"
#include "replay_player.h"
#include "settings.h"
#include "timedemo_stats.h"

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace obscura {
namespace replay { struct Script; }

// --replay / --timedemo: loads the script, checks every `set` against a scratch copy of the
// settings (a bad value fails before the first frame), and lets the script's header decide the
// level, seed, resolution, tick rate and start. Checks that the capture folder can be written.
// Returns null when the run is no replay. Throws replay::ScriptError / SettingsError.
std::unique_ptr<replay::Script> prepareReplay(Settings& settings, const SettingsParser& parser);

class ReplayHost {
public:
    virtual ~ReplayHost() = default;
    // A `set` (validated by prepareReplay, so this does not throw); `where` is file:line.
    virtual void applySetting(const std::string& key, const std::string& value, const std::string& where) = 0;
    virtual void injectInput(const ReplayInput& in) = 0;
    virtual void writeScreenshot(const std::string& path) = 0;
    virtual void finishFrame() = 0;  // waits for the frame's rendering
    virtual std::string stateHashHex() const = 0;
    // "x y z yaw pitch" of the eye now, in --start-pose's form (metres, degrees).
    virtual std::string cameraPose() const = 0;
    // Milliseconds of the smoke's work on the render thread in the frame just drawn: its ticks'
    // queueing and waits for the worker, and the uploads (smoke/smoke_pipeline.h).
    virtual double smokeRenderThreadMs() const = 0;
};

class ReplayDriver : public RunDriver {
public:
    // timed: a timedemo (frame times measured and shown); else captures show the fixed tick time.
    // drawEveryFrame false (--replay-draw captures): only the frames a capture reads and the last
    // one are drawn, the others' ticks run without a picture (a capture settles its own frames:
    // GameApp::writeScreenshot), so a replay test's second run checks that a capture does not
    // depend on the frames drawn before it, in a fraction of the time.
    ReplayDriver(const replay::Script& script, ReplayHost& host, bool timed, double tickRate, std::string captureDir,
                 bool drawEveryFrame = true);

    void beforeFrame(FrameHost& host) override;
    FramePlan plan(const FrameHost&) override;
    void afterFrame(FrameHost& host) override;
    bool finished(const FrameHost&) const override { return tick_ > player_.lastTick(); }
    // 3 when a hash diverged.
    int exitCode() const override { return diverged_ ? 3 : 0; }
    // The timedemo's statistics (empty for a replay).
    std::string report() const;

private:
    void writeCapture(const std::string& name);

    const replay::Script& script_;
    ReplayHost& host_;
    bool timed_;
    bool drawEveryFrame_;
    double fixedMs_;
    std::string captureDir_;
    ReplayPlayer player_;
    ReplayTick due_;
    std::int64_t tick_ = 0;
    double lastMs_;
    bool diverged_ = false;
    std::chrono::steady_clock::time_point start_;
    double cpuStart_ = 0;
    std::vector<double> frameMs_;
    std::vector<TimedemoSegment> segments_{1};
    std::vector<double> smokeMs_;  // smokeRenderThreadMs() a frame
};

}  // namespace obscura
