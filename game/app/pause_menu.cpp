// See pause_menu.h.
#include "app/pause_menu.h"

#include "ssao/ssao_modes.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace obscura {

namespace {
constexpr float kMenuMargin = 8;  // pixels kept clear round the menu at any window size
// Common 16:9 sizes; the current one is added if it is not among them.
const std::pair<int, int> kResolutions[] = {{960, 540}, {1280, 720}, {1600, 900}, {1920, 1080}};

std::string number(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}
}  // namespace

void PauseMenu::setOpen(bool open) {
    open_ = open;
    rebinding_.reset();
    if (!open) status_.clear();
}

bool PauseMenu::offerKey(const std::string& name) {
    if (!open_ || !rebinding_) return false;
    if (name != "escape") hooks_.set(std::string("bind-") + actionName(*rebinding_), name);
    rebinding_.reset();
    return true;
}

std::string PauseMenu::save() const {
    const std::string path = settings_.configFile.empty() ? defaultConfigPath() : settings_.configFile;
    std::vector<std::pair<std::string, std::string>> values = {
        {"width", std::to_string(settings_.width)},
        {"height", std::to_string(settings_.height)},
        {"mouse-sensitivity", number(settings_.mouseSensitivity)},
        {"invert-mouse", settings_.invertMouse ? "true" : "false"},
        {"fov", number(settings_.fov)},
        {"master-volume", number(settings_.masterVolume)},
        {"effects-volume", number(settings_.effectsVolume)},
        {"ssao", settings_.ssao},
    };
    for (const auto& [action, key] : settings_.bindings) values.emplace_back(std::string("bind-") + actionName(action), key);
    std::string text;
    if (std::ifstream in(path); in) text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
    // Write beside it and rename: a full disk or a crash never leaves half a config file.
    const std::string temp = path + ".new";
    {
        std::ofstream out(temp);
        out << updateConfigText(text, values);
        if (!out) return "cannot write " + temp;
    }
    std::filesystem::rename(temp, path, ec);
    return ec ? "cannot replace " + path + ": " + ec.message() : "saved to " + path;
}

void PauseMenu::draw() {
    if (!open_) return;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(io.DisplaySize.x - 2 * kMenuMargin, io.DisplaySize.y - 2 * kMenuMargin));
    ImGui::Begin("Paused", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
    auto click = [this] { if (hooks_.click) hooks_.click(); };

    if (ImGui::BeginCombo("resolution", (std::to_string(settings_.width) + " x " + std::to_string(settings_.height)).c_str())) {
        for (const auto& [w, h] : kResolutions)
            if (ImGui::Selectable((std::to_string(w) + " x " + std::to_string(h)).c_str(), w == settings_.width && h == settings_.height)) {
                click();
                hooks_.resize(w, h);
            }
        ImGui::EndCombo();
    }
    float sensitivity = static_cast<float>(settings_.mouseSensitivity);
    if (ImGui::SliderFloat("mouse sensitivity", &sensitivity, 0.1f, 5.0f, "%.2f")) hooks_.set("mouse-sensitivity", number(sensitivity));
    bool invert = settings_.invertMouse;
    if (ImGui::Checkbox("invert mouse", &invert)) hooks_.set("invert-mouse", invert ? "true" : "false");
    float fov = static_cast<float>(settings_.fov);
    if (ImGui::SliderFloat("field of view", &fov, 60.0f, 120.0f, "%.0f deg")) hooks_.set("fov", number(fov));
    float master = static_cast<float>(settings_.masterVolume), effects = static_cast<float>(settings_.effectsVolume);
    if (ImGui::SliderFloat("master volume", &master, 0.0f, 1.0f, "%.2f")) hooks_.set("master-volume", number(master));
    if (ImGui::SliderFloat("effects volume", &effects, 0.0f, 1.0f, "%.2f")) hooks_.set("effects-volume", number(effects));
    if (ImGui::BeginCombo("ambient occlusion", settings_.ssao.c_str())) {
        for (const auto& m : ssao::modeNames())
            if (ImGui::Selectable(m.c_str(), m == settings_.ssao)) {
                click();
                hooks_.set("ssao", m);
            }
        ImGui::EndCombo();
    }
    if (ImGui::CollapsingHeader("key bindings")) {
        // The list scrolls in its own region, so Resume, Save and Quit stay on screen however small
        // the window (at 960 x 540 the open list pushed them off the bottom): it takes what the
        // frame has left below it, at least three rows.
        const float row = ImGui::GetFrameHeightWithSpacing();
        const float list = row * (static_cast<float>(Action::Count) + 1);
        const float below = 3 * row + ImGui::GetStyle().WindowPadding.y * 2;
        const float avail = io.DisplaySize.y - 2 * kMenuMargin - ImGui::GetCursorPosY() - below;
        ImGui::BeginChild("bindings", ImVec2(0, std::clamp(list, 3 * row, std::max(3 * row, avail))));
        drawBindings();
        ImGui::EndChild();
    }

    ImGui::Separator();
    if (ImGui::Button("Resume")) {
        click();
        hooks_.resume();
    }
    ImGui::SameLine();
    if (ImGui::Button("Save settings")) {
        click();
        status_ = save();
    }
    ImGui::SameLine();
    if (ImGui::Button("Quit")) {
        click();
        hooks_.quit();
    }
    if (!status_.empty()) ImGui::TextUnformatted(status_.c_str());
    ImGui::End();
}

void PauseMenu::drawBindings() {
    ImGui::TextDisabled("click an action, then press its new key (Esc cancels)");
    for (int a = 0; a < static_cast<int>(Action::Count); ++a) {
        const auto action = static_cast<Action>(a);
        const auto it = settings_.bindings.find(action);
        const std::string key = rebinding_ == action ? "press a key..." : it == settings_.bindings.end() ? "-" : it->second;
        ImGui::PushID(a);
        if (ImGui::Button(key.c_str(), ImVec2(110, 0))) {
            if (hooks_.click) hooks_.click();
            rebinding_ = action;
        }
        ImGui::SameLine();
        ImGui::TextUnformatted(actionName(action));
        ImGui::PopID();
    }
}

}  // namespace obscura
