// libFuzzer: a config file's text through the settings table (every option's parser and range
// check) and the bindings check. A SettingsError is the expected refusal.
#include "settings.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const obscura::SettingsParser parser;
    const std::string text(reinterpret_cast<const char*>(data), size);
    obscura::Settings s;
    try {
        parser.parseConfigText(text, "fuzz.cfg", s);
        obscura::checkBindings(s);
        for (const auto& [k, v] : obscura::inputSettingValues(s)) parser.apply(k, v, s, "round trip");
    } catch (const obscura::SettingsError&) {
    }
    return 0;
}
