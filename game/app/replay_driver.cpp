// See replay_driver.h.
#include "app/replay_driver.h"

#include "replay/replay_script.h"

#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace obscura {

namespace fs = std::filesystem;

namespace {
// CPU time of the whole process, all threads (llvmpipe rasterises on its own threads).
double processCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}
// 10 frames: a new AO compositor compiles its shaders in its first two or three, the HUD's first
// frame has no crosshair yet. A timedemo leaves them out of its figures; a replay that draws only
// its captures (--replay-draw captures) still draws them, so its first capture is as every-frame's.
constexpr std::size_t kWarmupFrames = 10;
}  // namespace

std::unique_ptr<replay::Script> prepareReplay(Settings& settings, const SettingsParser& parser) {
    const std::string& path = !settings.timedemo.empty() ? settings.timedemo : settings.replay;
    if (path.empty()) return nullptr;
    // Every `set` is validated now, against a scratch copy: a bad value fails before the first frame.
    auto known = [&parser](const std::string& key) { return parser.isRuntime(key); };
    auto script = std::make_unique<replay::Script>(replay::loadScript(path, known));
    Settings scratch = settings;
    for (const auto& c : script->settings) parser.apply(c.name, c.value, scratch, script->fileName + ":" + std::to_string(c.line));
    for (const auto& c : script->commands)
        if (c.type == replay::Command::Type::Set)
            parser.apply(c.name, c.value, scratch, script->fileName + ":" + std::to_string(c.line));

    // The script's header decides the level, seed, resolution and tick rate.
    settings.level = replay::resolveLevel(*script, settings.dataDir);
    settings.seed = script->seed;
    settings.width = script->width;
    settings.height = script->height;
    settings.tickRate = script->tickRate;
    if (!script->start.empty()) {
        settings.startPose = script->start;
        settings.sources["start-pose"] = script->fileName + ":" + std::to_string(script->startLine);
    }
    settings.vsync = false;
    if (settings.replay.size()) settings.headless = true;
    // Frames left undrawn would leave a timedemo nothing to time, and --volume-dump reads the
    // volumetric buffer as the frames before it left it (not settled like a capture).
    if (settings.replayDraw == "captures" && (!settings.timedemo.empty() || !settings.volumeDump.empty()))
        throw SettingsError(sourceOf(settings, "replay-draw") +
                            ": setting 'replay-draw': captures needs --replay without --timedemo or --volume-dump");

    // (An unwritable capture folder is refused before the run, by main: checkOutputsWritable.)
    return script;
}

ReplayDriver::ReplayDriver(const replay::Script& script, ReplayHost& host, bool timed, double tickRate,
                           std::string captureDir, bool drawEveryFrame)
    : script_(script), host_(host), timed_(timed), drawEveryFrame_(drawEveryFrame || timed), fixedMs_(1000.0 / tickRate),
      captureDir_(std::move(captureDir)), player_(script), lastMs_(fixedMs_) {}

FramePlan ReplayDriver::plan(const FrameHost&) {
    FramePlan p{1, 1.0, timed_ ? lastMs_ : fixedMs_};
    p.draw = drawEveryFrame_ || tick_ < static_cast<std::int64_t>(kWarmupFrames) || !due_.captures.empty() ||
             tick_ == player_.lastTick();
    return p;
}

void ReplayDriver::beforeFrame(FrameHost&) {
    start_ = std::chrono::steady_clock::now();
    cpuStart_ = processCpuMs();
    due_ = player_.take(tick_);
    if (!due_.settings.empty() && !segments_.back().frameMs.empty()) segments_.push_back({});
    for (const auto* c : due_.settings) {
        host_.applySetting(c->name, c->value, script_.fileName + ":" + std::to_string(c->line));
        segments_.back().label += (segments_.back().label.empty() ? "" : " ") + c->name + "=" + c->value;
    }
    for (const auto& in : due_.inputs) host_.injectInput(in);
}

void ReplayDriver::afterFrame(FrameHost&) {
    if (timed_) host_.finishFrame();
    for (const auto* c : due_.captures) writeCapture(c->name);
    for (const auto* c : due_.hashes) {
        const std::string hex = host_.stateHashHex();
        std::cout << "hash " << tick_ << " " << hex << std::endl;  // flushed: tools/soak samples the process on it
        if (!c->value.empty() && c->value != hex && !diverged_) {
            diverged_ = true;
            std::cerr << script_.fileName << ":" << c->line << ": replay diverged at tick " << tick_ << ": expected "
                      << c->value << ", got " << hex << "\n";
        }
    }
    lastMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    frameMs_.push_back(lastMs_);
    segments_.back().frameMs.push_back(lastMs_);
    segments_.back().cpuMs.push_back(processCpuMs() - cpuStart_);
    smokeMs_.push_back(host_.smokeRenderThreadMs());
    ++tick_;
}

void ReplayDriver::writeCapture(const std::string& name) {
    // Write beside, then rename: a capture is never left half-written.
    const fs::path final = fs::path(captureDir_) / (name + ".png");
    const fs::path partial = fs::path(captureDir_) / (name + ".partial.png");
    host_.writeScreenshot(partial.string());
    fs::rename(partial, final);
    std::cout << "capture " << name << " " << final.string() << "\ncamera-pose " << host_.cameraPose() << "\n";
}

std::string ReplayDriver::report() const {
    if (!timed_) return "";
    auto segments = segments_;
    for (auto& seg : segments)
        if (seg.label.empty()) seg.label = "start";
    return formatFrameStats(computeFrameStats(frameMs_), script_.fileName) + formatSmokeThread(smokeMs_) +
           formatSegments(segments, kWarmupFrames);
}

}  // namespace obscura
