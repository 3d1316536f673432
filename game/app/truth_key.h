// The AO truth key in the game (T, `--truth`, the replay's `set truth ...`): the glue between the
// render view and engine_ext/ao_truth. Before each frame it asks the tracer for the current view
// (at a quarter of the viewport's width and height: the default AO buffer's size) and picks what
// the truth pass shows; after the frame, when a new reference snapshot arrived or the AO settings
// changed, it reads the mode's AO buffer back once, scores it and the `off` frame against the
// reference, and uploads the picture shown. The live game never waits for the tracer; headless
// captures do (waitDone), so a replay's capture of the truth is the finished reference's.
#pragma once

#include "ao_truth/progressive_ao.h"
#include "ao_truth/truth_compare.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace obscura {
namespace frame { class Frame; }
namespace ao_truth { class TruthView; }

// Of the viewport's width and height: the default AO buffer's size (settings.h, ssaoResolution),
// so the default mode is scored texel for texel; 320 x 180 at 720p, the size of ssao/README's table.
constexpr double kTruthScale = 0.25;

class TruthKey {
public:
    // `meshes`: the level's triangles, asked for the first time something is shown.
    TruthKey(frame::Frame& frame, std::function<std::vector<TriangleMesh>()> meshes, int threads);
    ~TruthKey();
    TruthKey(const TruthKey&) = delete;
    TruthKey& operator=(const TruthKey&) = delete;

    void set(ao_truth::Show show, int rays);
    ao_truth::Show show() const { return show_; }
    // The mode or its knobs changed: score again after the next frame.
    void aoChanged() { rescore_ = true; }

    // Before the frame renders.
    void beforeRender(const CameraPose& pose, int viewportWidth, int viewportHeight, double radius);
    // After it rendered: `readAo` gives the mode's AO buffer (red channel, top row first) and its size.
    using AoReader = std::function<std::vector<float>(int& width, int& height)>;
    void afterRender(const AoReader& readAo);
    std::vector<std::string> hudLines(const std::string& mode) const;

    // Headless captures only: blocks until the reference is finished; throws after 10 minutes.
    void waitDone() const;

private:
    void afterRenderShown(const AoReader& readAo);

    frame::Frame& frame_;
    std::function<std::vector<TriangleMesh>()> meshes_;
    int threads_;
    std::unique_ptr<ao_truth::TruthView> view_;
    std::unique_ptr<ao_truth::ProgressiveAo> tracer_;  // made the first time something is shown
    ao_truth::Show show_ = ao_truth::Show::Off;
    int rays_ = 256;
    ao_truth::Request request_;
    std::shared_ptr<const ao_truth::Snapshot> snapshot_;  // the latest taken
    std::optional<ao_truth::Score> score_;
    std::vector<std::uint8_t> heatMap_;
    bool rescore_ = false;
    std::uint64_t uploaded_ = 0;  // the snapshot serial of the picture on the GPU ...
    ao_truth::Show uploadedShow_ = ao_truth::Show::Off;  // ... which picture it is ...
    bool pictureOfThisView_ = false;  // ... and whether it is of the view being traced
    // The render thread's time in this class while something is shown (printed at exit: the
    // README's cost figures), and in the read-backs with their scoring and upload.
    struct Cost {
        long frames = 0, readBacks = 0;
        double ms = 0, maxMs = 0, readBackMs = 0;
    } cost_;
    double frameMs_ = 0;
};

}  // namespace obscura
