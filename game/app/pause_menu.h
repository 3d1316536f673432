// The pause menu (Esc): resolution, mouse sensitivity, field of view, volumes, AO mode and key
// bindings, applied as they change and saved to the config file. ImGui, drawn by the HUD. Every
// change goes through the settings table (the same names and range checks as the command line).
#pragma once

#include "settings.h"

#include <functional>
#include <optional>
#include <string>

namespace obscura {

class PauseMenu {
public:
    struct Hooks {
        // Apply one setting now (GameApp::applySetting: parser + side effects).
        std::function<void(const std::string& key, const std::string& value)> set;
        std::function<void(int width, int height)> resize;
        std::function<void()> resume, quit, click;
    };
    PauseMenu(const Settings& settings, Hooks hooks) : settings_(settings), hooks_(std::move(hooks)) {}

    bool isOpen() const { return open_; }
    void setOpen(bool open);
    // Builds the menu's ImGui window when open (between the HUD's NewFrame and render).
    void draw();
    // While a binding waits for its key, the next key or mouse button goes to it (true = taken).
    bool offerKey(const std::string& name);
    // Writes the settings the menu shows into the config file, keeping everything else in it.
    // Returns a status line (where, or why not).
    std::string save() const;

private:
    void drawBindings();
    const Settings& settings_;
    Hooks hooks_;
    bool open_ = false;
    std::optional<Action> rebinding_;
    std::string status_;
};

}  // namespace obscura
