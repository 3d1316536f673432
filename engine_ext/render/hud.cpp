// See hud.h.
#include "render/hud.h"

#include <OgreImGuiOverlay.h>
#include <OgreMaterialManager.h>
#include <OgreOverlayManager.h>
#include <OgreTextureManager.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace obscura::render {

namespace {
constexpr std::size_t kFrameHistory = 120;  // two seconds at 60 Hz: spikes stay visible a while

// Text with a dark drop shadow so it reads on bright and dark walls.
void shadowedText(ImDrawList* dl, ImVec2 pos, ImU32 colour, const char* text) {
    dl->AddText(ImVec2(pos.x + 1, pos.y + 1), IM_COL32(0, 0, 0, 200), text);
    dl->AddText(pos, colour, text);
}
}  // namespace

Hud::Hud() {
    overlay_ = new Ogre::ImGuiOverlay();
    overlay_->setZOrder(300);
    overlay_->show();
    Ogre::OverlayManager::getSingleton().addOverlay(overlay_);  // the manager owns and deletes it
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written into the working directory
}

Hud::~Hud() {
    Ogre::OverlayManager::getSingleton().destroy(overlay_);
    // OGRE 1.12's ImGuiOverlay leaves its font texture and material behind under fixed names: the
    // next level's HUD (trigger_changelevel) would meet "ImGui/FontTex already exists".
    for (Ogre::ResourceManager* rm : {static_cast<Ogre::ResourceManager*>(Ogre::TextureManager::getSingletonPtr()),
                                      static_cast<Ogre::ResourceManager*>(Ogre::MaterialManager::getSingletonPtr())})
        for (const char* name : {"ImGui/FontTex", "ImGui/material"})
            if (const Ogre::ResourcePtr r = rm->getResourceByName(name, Ogre::RGN_AUTODETECT)) rm->remove(r);
}

void Hud::addPanelSection(std::string title, std::function<void()> draw) {
    sections_.emplace_back(std::move(title), std::move(draw));
}

void Hud::recordFrame(double frameMs) {
    frameHistory_.push_back(static_cast<float>(frameMs));
    while (frameHistory_.size() > kFrameHistory) frameHistory_.pop_front();
}

void Hud::update(const HudState& state) {
    Ogre::ImGuiOverlay::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 centre(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f);

    if (!state.visible) {
        if (panelVisible_) drawPanel();
        if (menu_) menu_();
        return;
    }
    // Crosshair: four short strokes with a dark outline so it reads on bright and dark walls.
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const float gap = 4.0f, len = 8.0f;
    const ImVec2 dirs[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& d : dirs) {
        if (!state.crosshair) break;
        const ImVec2 a(centre.x + d.x * gap, centre.y + d.y * gap);
        const ImVec2 b(centre.x + d.x * (gap + len), centre.y + d.y * (gap + len));
        dl->AddLine(a, b, IM_COL32(0, 0, 0, 160), 4.0f);
        dl->AddLine(a, b, IM_COL32(255, 255, 255, 230), 2.0f);
    }

    // Hit marker: a diagonal cross around the crosshair that fades out.
    if (state.hitMarker > 0) {
        const auto alpha = static_cast<int>(255 * std::min(state.hitMarker, 1.0));
        for (const auto& d : {ImVec2(1, 1), ImVec2(-1, 1), ImVec2(1, -1), ImVec2(-1, -1)}) {
            const ImVec2 a(centre.x + d.x * 6, centre.y + d.y * 6), b(centre.x + d.x * 13, centre.y + d.y * 13);
            dl->AddLine(a, b, IM_COL32(255, 60, 40, alpha), 2.5f);
        }
    }

    char line[96];
    std::snprintf(line, sizeof line, "%.2f ms%s", state.frameMs, state.frameMsIsFixed ? " (fixed tick)" : "");
    ImVec2 pos(10, 8);
    shadowedText(dl, pos, IM_COL32(255, 255, 255, 255), line);
    for (const auto& s : state.status) {
        pos.y += 16;
        shadowedText(dl, pos, IM_COL32(255, 240, 200, 255), s.c_str());
    }
    recordFrame(state.frameMs);
    drawFrameGraph();
    drawCombat(state);
    drawCentreMessage(state.centreMessage);

    if (panelVisible_) drawPanel();
    if (menu_) menu_();
}

void Hud::drawFrameGraph() {
    // Bars of the recent frame times, bottom left; the 16.7 ms (60 Hz) line for scale. At most
    // 120 x 36 pixels, less on small frames so it never covers the view.
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const ImGuiIO& io = ImGui::GetIO();
    const float width = std::min(120.0f, io.DisplaySize.x * 0.15f), height = std::min(36.0f, io.DisplaySize.y * 0.08f);
    const ImVec2 origin(10, io.DisplaySize.y - height - 10);
    const float top = std::max(33.4f, *std::max_element(frameHistory_.begin(), frameHistory_.end()));
    dl->AddRectFilled(origin, ImVec2(origin.x + width, origin.y + height), IM_COL32(0, 0, 0, 90));
    const float barW = width / static_cast<float>(kFrameHistory);
    float x = origin.x + width - barW * static_cast<float>(frameHistory_.size());
    for (float ms : frameHistory_) {
        const float h = height * std::min(ms / top, 1.0f);
        const ImU32 c = ms > 33.4f ? IM_COL32(255, 90, 60, 220) : ms > 16.7f ? IM_COL32(255, 210, 80, 220) : IM_COL32(120, 230, 120, 220);
        dl->AddRectFilled(ImVec2(x, origin.y + height - h), ImVec2(x + barW, origin.y + height), c);
        x += barW;
    }
    const float y60 = origin.y + height - height * 16.7f / top;
    dl->AddLine(ImVec2(origin.x, y60), ImVec2(origin.x + width, y60), IM_COL32(255, 255, 255, 120), 1.0f);
}

void Hud::drawCentreMessage(const std::string& text) {
    // Each line centred, the block's top a third down the view (Quake's SCR_DrawCenterString
    // starts at 35 % of the height), clear of the crosshair.
    if (text.empty()) return;
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const ImGuiIO& io = ImGui::GetIO();
    float y = io.DisplaySize.y * 0.35f;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string line = text.substr(start, end - start);
        const float w = ImGui::CalcTextSize(line.c_str()).x;
        shadowedText(dl, ImVec2(std::floor((io.DisplaySize.x - w) * 0.5f), y), IM_COL32(255, 255, 255, 255), line.c_str());
        y += ImGui::GetTextLineHeightWithSpacing();
        start = end + 1;
    }
}

void Hud::drawCombat(const HudState& state) {
    if (state.magazineSize <= 0) return;
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const ImGuiIO& io = ImGui::GetIO();
    char text[96];
    // Ammo, bottom right: magazine / reserve, red when the magazine runs low.
    std::snprintf(text, sizeof text, "%d / %d", state.magazine, state.reserve);
    const bool low = state.magazine * 4 <= state.magazineSize;
    const ImVec2 size = ImGui::CalcTextSize(text);
    const ImVec2 ammoPos(io.DisplaySize.x - size.x * 2 - 20, io.DisplaySize.y - size.y * 2 - 16);
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize() * 2, ImVec2(ammoPos.x + 1, ammoPos.y + 1), IM_COL32(0, 0, 0, 200), text);
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize() * 2, ammoPos, low ? IM_COL32(255, 90, 60, 255) : IM_COL32(255, 255, 255, 255), text);
    if (state.reloadProgress >= 0) {
        const ImVec2 a(io.DisplaySize.x * 0.5f - 50, io.DisplaySize.y * 0.5f + 30);
        dl->AddRectFilled(a, ImVec2(a.x + 100, a.y + 5), IM_COL32(0, 0, 0, 140));
        dl->AddRectFilled(a, ImVec2(a.x + 100 * static_cast<float>(state.reloadProgress), a.y + 5), IM_COL32(255, 255, 255, 220));
        shadowedText(dl, ImVec2(a.x + 28, a.y + 8), IM_COL32(255, 255, 255, 230), "reloading");
    }
    if (state.throwCharge >= 0) {
        const ImVec2 a(io.DisplaySize.x * 0.5f - 50, io.DisplaySize.y * 0.5f + 46);
        dl->AddRectFilled(a, ImVec2(a.x + 100, a.y + 5), IM_COL32(0, 0, 0, 140));
        dl->AddRectFilled(a, ImVec2(a.x + 100 * static_cast<float>(state.throwCharge), a.y + 5), IM_COL32(120, 200, 255, 230));
    }
    // Score, top right.
    std::snprintf(text, sizeof text, "score %d", state.score);
    const ImVec2 scoreSize = ImGui::CalcTextSize(text);
    shadowedText(dl, ImVec2(io.DisplaySize.x - scoreSize.x - 12, 8), IM_COL32(255, 255, 255, 255), text);
}

void Hud::drawPanel() {
    ImGui::SetNextWindowPos(ImVec2(10, 60), ImGuiCond_FirstUseEver);
    ImGui::Begin("Obscura debug", &panelVisible_, ImGuiWindowFlags_AlwaysAutoResize);
    for (const auto& [title, draw] : sections_)
        if (ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) draw();
    ImGui::End();
}

}  // namespace obscura::render
