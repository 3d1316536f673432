// Our key names (settings.h keyNames()) <-> SDL keycodes/scancodes. The same table serves live
// keyboard events and the SDL events a replay injects, so both go through the same bindings.
#pragma once

#include <optional>
#include <string>

namespace obscura {

// Name of an SDL keycode, or empty if the key is not one we name.
std::string keyNameFromKeycode(int sdlKeycode);
// SDL keycode and scancode for a key name (keyboard keys only, not mouse1..3).
std::optional<int> keycodeFromKeyName(const std::string& name);
std::optional<int> scancodeFromKeyName(const std::string& name);
// Mouse buttons: our names mouse1/mouse2/mouse3 are left/right/middle.
std::string keyNameFromMouseButton(int bitesButton);

}  // namespace obscura
