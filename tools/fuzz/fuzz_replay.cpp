// libFuzzer: a replay script through the parser; what it accepts must format and parse back to
// the same script (the property --record relies on). A ScriptError is the expected refusal.
#include "replay/replay_script.h"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    using namespace obscura::replay;
    Script s;
    try {
        s = parseScript(text, "fuzz.replay", [](const std::string& k) { return k.size() < 32; });
    } catch (const ScriptError&) {
        return 0;
    }
    try {
        if (parseScript(formatScript(s), "again.replay") != s) std::abort();
    } catch (const ScriptError&) {
        std::abort();  // an accepted script must always format to an accepted one
    }
    if (!s.start.empty() && !checkPose(s.start).empty()) std::abort();
    s.endTick();
    s.commandsAt(s.endTick());
    return 0;
}
