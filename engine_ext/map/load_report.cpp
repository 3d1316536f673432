// See load_report.h.
#include "map/load_report.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace obscura::map {

std::vector<std::string> warningLines(const std::vector<std::string>& warnings, std::size_t maxLines) {
    std::vector<std::string> lines(warnings.begin(), warnings.begin() + static_cast<std::ptrdiff_t>(std::min(maxLines, warnings.size())));
    if (warnings.size() > maxLines)
        lines.push_back("obscura: ... and " + std::to_string(warnings.size() - maxLines) + " more warnings (see the log)");
    return lines;
}

std::string summaryLine(const Level& level, std::size_t warningCount, const LoadTimes& times) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "parse %.1f ms, compile %.1f ms, session %.1f ms, scene %.1f ms; ", times.parseMs, times.compileMs,
                  times.sessionMs, times.sceneMs);
    std::string s = "obscura: loaded " + level.sourcePath + ": " + buf;
    s += std::to_string(level.brushes.size()) + " brushes, " + std::to_string(level.entities.size()) + " entities" +
         (level.leftOutEntities ? " (" + std::to_string(level.leftOutEntities) + " more left out at skill " + std::to_string(level.skill) + ")" : "") + ", " +
         std::to_string(level.lights.size()) + " lights, " + std::to_string(level.models.size()) + " models; " +
         std::to_string(warningCount) + (warningCount == 1 ? " warning" : " warnings") + "; unknown classes: ";

    const auto& names = level.unknownClassnames;
    std::vector<std::size_t> order(names.size());
    std::iota(order.begin(), order.end(), 0);
    const auto count = [&](std::size_t i) { return i < level.unknownClassCounts.size() ? level.unknownClassCounts[i] : 1; };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return count(a) != count(b) ? count(a) > count(b) : names[a] < names[b];
    });
    if (order.empty()) return s + "none";
    for (std::size_t k = 0; k < order.size() && k < kMaxUnknownNames; ++k)
        s += (k ? ", " : "") + names[order[k]] + " \u00d7" + std::to_string(count(order[k]));
    if (order.size() > kMaxUnknownNames) s += " and " + std::to_string(order.size() - kMaxUnknownNames) + " more classes";
    return s;
}

}  // namespace obscura::map
