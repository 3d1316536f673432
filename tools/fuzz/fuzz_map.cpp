// libFuzzer: a .map text through everything a level load does before OGRE: parse, brush compile,
// entity validation. A MapError is the expected way to refuse input; anything else (a sanitizer
// report, another exception, a crash, a timeout) is a finding.
#include "map/map_compile.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const obscura::map::MapFile map = obscura::map::parseMap(text, "fuzz.map");
        std::vector<std::string> warnings;
        const obscura::map::Level level = obscura::map::compileLevel(map, {}, &warnings);
        // What compileLevel accepts must be usable downstream: finite vertices, models in range.
        for (const auto& b : level.brushes)
            for (const auto& f : b.faces)
                for (const auto& v : f.vertices)
                    if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) || !std::isfinite(v.position.z)) std::abort();
        for (const auto& m : level.models)
            if (!(m.scale >= obscura::map::kMinModelScale && m.scale <= obscura::map::kMaxModelScale)) std::abort();
        const obscura::map::Aabb box = obscura::map::placementRegion(level);
        if (level.hasPlayerStart && !std::isfinite(level.playerStart.x)) std::abort();
        (void)box;
    } catch (const obscura::map::MapError&) {
    }
    return 0;
}
