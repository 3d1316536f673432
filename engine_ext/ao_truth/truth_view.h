// The truth key's pass (OGRE glue): over the frame's output, the traced reference or the heat map
// (an RGBA8 texture uploaded from the CPU when its picture changes), or the active mode's AO
// buffer as it is scored (`aoMap`, bound by the frame). Out of the chain while nothing is shown.
// The tracer, the scores and the pictures are plain C++ (progressive_ao.h, truth_compare.h).
#pragma once

#include "ao_truth/truth_compare.h"
#include "frame/technique.h"

#include <OgreTexture.h>

#include <cstdint>
#include <vector>

namespace obscura::ao_truth {

class TruthView : public frame::Technique {
public:
    TruthView();  // a 1x1 black picture until the first upload
    ~TruthView() override;
    TruthView(const TruthView&) = delete;
    TruthView& operator=(const TruthView&) = delete;

    std::string folder() const override { return "engine_ext/ao_truth"; }
    frame::Stage stage() const override { return frame::Stage::Output; }
    std::string compositor() const override { return show_ == Show::Off ? std::string() : "Obscura/AoTruth/Show"; }
    // The picture's size: a new texture is bound again when the chain is rebuilt.
    std::string configuration() const override;
    void setup(Ogre::uint32 passId, Ogre::Pass& pass) override;
    void bind(Ogre::uint32 passId, Ogre::Pass& pass, frame::Uniforms& u, const frame::FrameContext& ctx) override;

    // Off: out of the chain; Reference and HeatMap: the uploaded picture; Mode: the AO buffer.
    void show(Show s) { show_ = s; }
    // An RGBA8 picture, top row first (truth_compare.h: greyRgba, heatMapRgba).
    void upload(int width, int height, const std::vector<std::uint8_t>& rgba);

private:
    Show show_ = Show::Off;
    Ogre::TexturePtr picture_;
    int width_ = 0, height_ = 0;
};

}  // namespace obscura::ao_truth
