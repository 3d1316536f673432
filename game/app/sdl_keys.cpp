// See sdl_keys.h.
#include "app/sdl_keys.h"

#include "settings.h"

#include <OgreInput.h>
#include <SDL2/SDL.h>

#include <map>

namespace obscura {

namespace {
const std::map<std::string, int>& namedKeycodes() {
    static const std::map<std::string, int> table = [] {
        std::map<std::string, int> t = {
            {"space", SDLK_SPACE},   {"return", SDLK_RETURN}, {"escape", SDLK_ESCAPE}, {"tab", SDLK_TAB},
            {"backspace", SDLK_BACKSPACE}, {"lshift", SDLK_LSHIFT}, {"rshift", SDLK_RSHIFT},
            {"lctrl", SDLK_LCTRL},   {"rctrl", SDLK_RCTRL},   {"lalt", SDLK_LALT},     {"ralt", SDLK_RALT},
            {"up", SDLK_UP},         {"down", SDLK_DOWN},     {"left", SDLK_LEFT},     {"right", SDLK_RIGHT},
            {"minus", SDLK_MINUS},   {"equals", SDLK_EQUALS}, {"comma", SDLK_COMMA},   {"period", SDLK_PERIOD},
            {"slash", SDLK_SLASH},   {"grave", SDLK_BACKQUOTE}};
        for (char c = 'a'; c <= 'z'; ++c) t[std::string(1, c)] = c;  // SDL letter keycodes are ASCII
        for (char c = '0'; c <= '9'; ++c) t[std::string(1, c)] = c;
        for (int i = 0; i < 12; ++i) t["f" + std::to_string(i + 1)] = SDLK_F1 + i;
        return t;
    }();
    return table;
}
}  // namespace

std::string keyNameFromKeycode(int sdlKeycode) {
    for (const auto& [name, code] : namedKeycodes())
        if (code == sdlKeycode) return name;
    return {};
}

std::optional<int> keycodeFromKeyName(const std::string& name) {
    const auto& t = namedKeycodes();
    const auto it = t.find(name);
    if (it == t.end()) return std::nullopt;
    return it->second;
}

std::optional<int> scancodeFromKeyName(const std::string& name) {
    const auto k = keycodeFromKeyName(name);
    if (!k) return std::nullopt;
    return static_cast<int>(SDL_GetScancodeFromKey(*k));
}

std::string keyNameFromMouseButton(int bitesButton) {
    switch (bitesButton) {
        case OgreBites::BUTTON_LEFT: return "mouse1";
        case OgreBites::BUTTON_RIGHT: return "mouse2";
        case OgreBites::BUTTON_MIDDLE: return "mouse3";
        default: return {};
    }
}

}  // namespace obscura
