// See debug_panel.h.
#include "app/debug_panel.h"

#include "app/render_view.h"
#include "frame/frame_knobs.h"
#include "render/hud.h"
#include "render/level_geometry.h"
#include "session.h"
#include "ssao/ssao_knobs.h"

#include <imgui.h>

#include <cmath>

namespace obscura {

DebugPanel::DebugPanel(RenderView& view, const Session& session, Settings& settings, std::function<void()> aoChanged)
    : view_(view), session_(session), settings_(settings), aoChanged_(std::move(aoChanged)) {
    view_.hud().addPanelSection("Player", [this] { drawPlayer(); });
    view_.hud().addPanelSection("Ambient occlusion", [this] { drawAo(); });
    view_.hud().addPanelSection("Level", [this] { drawLevel(); });
}

bool DebugPanel::visible() const { return view_.hud().panelVisible(); }
void DebugPanel::setVisible(bool on) { view_.hud().setPanelVisible(on); }

void DebugPanel::drawPlayer() const {
    const auto& p = session_.sim().player();
    ImGui::Text("tick %llu", static_cast<unsigned long long>(session_.tick()));
    ImGui::Text("feet %.2f %.2f %.2f", p.feet.x, p.feet.y, p.feet.z);
    // Yaw and pitch as --start-pose takes them (degrees); the state as Quake's waterlevel sees it.
    ImGui::Text("yaw %.1f pitch %.1f", p.yaw * 180.0 / 3.14159265358979323846, p.pitch * 180.0 / 3.14159265358979323846);
    const char* state = p.waterLevel >= 2 ? (p.waterLevel == 3 ? "under water" : "swimming")
                        : p.onGround      ? (p.waterLevel == 1 ? "wading" : "on ground")
                                          : "in air";
    ImGui::Text("speed %.2f m/s %s%s", std::hypot(p.velocity.x, p.velocity.z), state, p.crouching ? ", crouching" : "");
}

void DebugPanel::drawAo() {
    ImGui::Text("mode: %s (O / Shift+O)", view_.aoStatus().c_str());
    float radius = static_cast<float>(settings_.ssaoRadius), largeRadius = static_cast<float>(settings_.ssaoLargeRadius);
    float intensity = static_cast<float>(settings_.ssaoIntensity);
    float exposure = static_cast<float>(settings_.exposure);
    // Ranges from the knob tables (ssao/ssao_knobs.h, frame/frame_knobs.h).
    const auto slider = [](const char* label, float* v, const Knob& k) {
        return ImGui::SliderFloat(label, v, static_cast<float>(k.min), static_cast<float>(k.max));
    };
    bool changed = slider("radius (m)", &radius, ssao::kRadius);
    changed |= slider("large radius (m)", &largeRadius, ssao::kLargeRadius);
    changed |= slider("intensity", &intensity, ssao::kIntensity);
    changed |= ImGui::SliderInt("samples", &settings_.ssaoSamples, static_cast<int>(ssao::kSamples.min),
                                static_cast<int>(ssao::kSamples.max));
    changed |= ImGui::Checkbox("AO only", &settings_.aoOnly);
    changed |= slider("exposure", &exposure, frame::kExposure);
    if (changed) {
        settings_.ssaoRadius = radius;
        settings_.ssaoLargeRadius = largeRadius;
        settings_.ssaoIntensity = intensity;
        settings_.exposure = exposure;
        aoChanged_();
    }
}

void DebugPanel::drawLevel() const {
    const auto& st = view_.levelStats();
    ImGui::Text("%zu batches, %zu triangles, %zu lights", st.batches, st.triangles, st.lights);
}

}  // namespace obscura
