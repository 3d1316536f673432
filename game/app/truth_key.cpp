// See truth_key.h.
#include "app/truth_key.h"

#include "ao_truth/truth_view.h"
#include "frame/frame.h"

#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>

namespace obscura {

using ao_truth::Show;

TruthKey::TruthKey(frame::Frame& frame, std::function<std::vector<TriangleMesh>()> meshes, int threads)
    : frame_(frame), meshes_(std::move(meshes)), threads_(threads), view_(std::make_unique<ao_truth::TruthView>()) {
    frame_.add(*view_);
}

TruthKey::~TruthKey() {
    if (cost_.frames == 0) return;
    std::cout << "truth: render thread " << cost_.ms / cost_.frames << " ms a frame over " << cost_.frames
              << " frames shown (max " << cost_.maxMs << " ms); " << cost_.readBacks << " read-backs, "
              << (cost_.readBacks ? cost_.readBackMs / cost_.readBacks : 0.0) << " ms each\n";
}

namespace {
double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

void TruthKey::set(Show show, int rays) {
    show_ = show;
    rays_ = rays;
    if (show_ == Show::Off && tracer_) tracer_->cancel();  // no tracing while nothing is shown
    if (show_ != Show::Off && !tracer_) {
        try {
            tracer_ = std::make_unique<ao_truth::ProgressiveAo>(meshes_(), threads_);
        } catch (const std::exception& e) {  // a misc_model's mesh gone since the load: no truth, the game goes on
            std::cerr << "obscura: truth key: " << e.what() << "; the truth stays off\n";
            show_ = Show::Off;
        }
    }
    rescore_ = true;
}

void TruthKey::beforeRender(const CameraPose& pose, int viewportWidth, int viewportHeight, double radius) {
    if (show_ == Show::Off) {
        view_->show(Show::Off);
        return;
    }
    const auto t0 = std::chrono::steady_clock::now();
    request_.pose = pose;
    request_.width = std::max(1, static_cast<int>(std::lround(viewportWidth * kTruthScale)));
    request_.height = std::max(1, static_cast<int>(std::lround(viewportHeight * kTruthScale)));
    request_.radius = radius;
    request_.rays = rays_;
    tracer_->request(request_);
    auto latest = tracer_->latest();
    if (!latest) {  // a new view: nothing to show or say until its first pass
        score_.reset();
        pictureOfThisView_ = false;
    }
    if (latest && (!snapshot_ || latest->serial != snapshot_->serial)) {
        rescore_ = true;
        if (latest->done)  // the figure engine_ext/ao_truth/README.md gives
            std::cout << "truth: reference " << request_.width << "x" << request_.height << ", " << latest->rays
                      << " rays, finished in " << latest->seconds << " s (" << threads_ << " thread(s))\n";
    }
    snapshot_ = std::move(latest);
    // The mode's AO buffer is live; the reference and the heat map wait for a snapshot of this view.
    // (an earlier pass's picture of this view stays until the next one is uploaded after this frame).
    view_->show(show_ == Show::Mode || (pictureOfThisView_ && uploadedShow_ == show_) ? show_ : Show::Off);
    ++cost_.frames;
    frameMs_ = msSince(t0);
}

void TruthKey::afterRender(const AoReader& readAo) {
    if (show_ == Show::Off) return;
    const auto t0 = std::chrono::steady_clock::now();
    if (snapshot_) afterRenderShown(readAo);
    frameMs_ += msSince(t0);
    cost_.ms += frameMs_;
    cost_.maxMs = std::max(cost_.maxMs, frameMs_);
}

void TruthKey::afterRenderShown(const AoReader& readAo) {
    const ssao::AoImage& ref = snapshot_->image;
    if (rescore_) {
        const auto t0 = std::chrono::steady_clock::now();
        // Once per refinement or settings change: the read-back waits for the GPU (README: its cost).
        int w = 0, h = 0;
        const std::vector<float> buffer = readAo(w, h);
        const std::vector<float> mode = ao_truth::resampleNearest(buffer, w, h, ref.width, ref.height);
        score_ = ao_truth::score(ref, mode);
        score_->rays = snapshot_->rays;
        heatMap_ = ao_truth::heatMapRgba(ref, mode);
        rescore_ = false;
        uploaded_ = 0;
        ++cost_.readBacks;
        cost_.readBackMs += msSince(t0);
    }
    if ((show_ == Show::Reference || show_ == Show::HeatMap) && (uploaded_ != snapshot_->serial || uploadedShow_ != show_)) {
        view_->upload(ref.width, ref.height, show_ == Show::Reference ? ao_truth::greyRgba(ref.ao) : heatMap_);
        uploaded_ = snapshot_->serial;
        uploadedShow_ = show_;
        pictureOfThisView_ = true;
    }
}

std::vector<std::string> TruthKey::hudLines(const std::string& mode) const {
    ao_truth::HudFacts f;
    f.show = show_;
    f.mode = mode;
    f.width = request_.width;
    f.height = request_.height;
    f.rays = snapshot_ ? snapshot_->rays : 0;
    f.totalRays = rays_;
    f.score = score_ ? &*score_ : nullptr;
    return ao_truth::hudLines(f);
}

void TruthKey::waitDone() const {
    if (show_ == Show::Off) return;
    // A hang detector: 256 rays at 320 x 180 take about a second here, 4096 rays about 15 s.
    if (!tracer_->waitDone(std::chrono::minutes(10)))
        throw std::runtime_error("truth key: the reference was not finished after 10 minutes");
}

}  // namespace obscura
