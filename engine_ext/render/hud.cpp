// See hud.h.
#include "render/hud.h"

#include <OgreImGuiOverlay.h>
#include <OgreOverlayManager.h>
#include <imgui.h>

#include <cstdio>

namespace obscura::render {

Hud::Hud() {
    overlay_ = new Ogre::ImGuiOverlay();
    overlay_->setZOrder(300);
    overlay_->show();
    Ogre::OverlayManager::getSingleton().addOverlay(overlay_);  // the manager owns and deletes it
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written into the working directory
}

Hud::~Hud() { Ogre::OverlayManager::getSingleton().destroy(overlay_); }

void Hud::addPanelSection(std::string title, std::function<void()> draw) {
    sections_.emplace_back(std::move(title), std::move(draw));
}

void Hud::update(const HudState& state) {
    Ogre::ImGuiOverlay::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 centre(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f);

    if (!state.visible) {
        if (panelVisible_) drawPanel();
        return;
    }
    // Crosshair: four short strokes with a dark outline so it reads on bright and dark walls.
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const float gap = 4.0f, len = 8.0f;
    const ImVec2 dirs[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& d : dirs) {
        const ImVec2 a(centre.x + d.x * gap, centre.y + d.y * gap);
        const ImVec2 b(centre.x + d.x * (gap + len), centre.y + d.y * (gap + len));
        dl->AddLine(a, b, IM_COL32(0, 0, 0, 160), 4.0f);
        dl->AddLine(a, b, IM_COL32(255, 255, 255, 230), 2.0f);
    }

    char line[96];
    std::snprintf(line, sizeof line, "%.2f ms%s", state.frameMs, state.frameMsIsFixed ? " (fixed tick)" : "");
    ImVec2 pos(10, 8);
    dl->AddText(ImVec2(pos.x + 1, pos.y + 1), IM_COL32(0, 0, 0, 200), line);
    dl->AddText(pos, IM_COL32(255, 255, 255, 255), line);
    for (const auto& s : state.status) {
        pos.y += 16;
        dl->AddText(ImVec2(pos.x + 1, pos.y + 1), IM_COL32(0, 0, 0, 200), s.c_str());
        dl->AddText(pos, IM_COL32(255, 240, 200, 255), s.c_str());
    }

    if (panelVisible_) drawPanel();
}

void Hud::drawPanel() {
    ImGui::SetNextWindowPos(ImVec2(10, 60), ImGuiCond_FirstUseEver);
    ImGui::Begin("Obscura debug", &panelVisible_, ImGuiWindowFlags_AlwaysAutoResize);
    for (const auto& [title, draw] : sections_)
        if (ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) draw();
    ImGui::End();
}

}  // namespace obscura::render
