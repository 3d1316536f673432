// Debug views of the frame's G-buffer and light (V cycles them with the frame's other views):
// albedo, normal, depth, the direct light and the HDR light before the tone map. A pass of the
// output stage that draws over the frame's output while one of its views is shown, and is out of
// the chain otherwise. It is also the example of how small a new pass is: this folder,
// media/gbuffer_view/, shaders/gbuffer_view/ and the line in frame.cpp that adds it.
#pragma once

#include "frame/technique.h"

namespace obscura::gbuffer_view {

class GBufferView : public frame::Technique {
public:
    std::string folder() const override { return "engine_ext/gbuffer_view"; }
    frame::Stage stage() const override { return frame::Stage::Output; }
    std::string compositor() const override { return view_ < 0 ? std::string() : "Obscura/GBufferView/Show"; }
    std::string configuration() const override { return std::to_string(view_); }
    void bind(Ogre::uint32 passId, Ogre::Pass& pass, frame::Uniforms& u, const frame::FrameContext& ctx) override;
    std::vector<std::string> views() const override;
    void showView(const std::string& view) override;

private:
    int view_ = -1;  // index into views(), -1: none shown
};

}  // namespace obscura::gbuffer_view
