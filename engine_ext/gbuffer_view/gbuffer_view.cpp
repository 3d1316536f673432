// See gbuffer_view.h.
#include "gbuffer_view/gbuffer_view.h"

#include <algorithm>

namespace obscura::gbuffer_view {

std::vector<std::string> GBufferView::views() const { return {"albedo", "normal", "depth", "direct-light", "hdr-light"}; }

void GBufferView::showView(const std::string& view) {
    const auto all = views();
    const auto at = std::find(all.begin(), all.end(), view);
    view_ = at == all.end() ? -1 : static_cast<int>(at - all.begin());
}

void GBufferView::bind(Ogre::uint32, Ogre::Pass&, frame::Uniforms& u, const frame::FrameContext&) {
    u.set("view", static_cast<float>(view_));
}

}  // namespace obscura::gbuffer_view
