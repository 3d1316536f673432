// See timedemo_stats.h.
#include "timedemo_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace obscura {

namespace {
double nearestRank(const std::vector<double>& sorted, double p) {
    const auto n = sorted.size();
    auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(n)));
    rank = std::clamp<std::size_t>(rank, 1, n);
    return sorted[rank - 1];
}
}  // namespace

FrameStats computeFrameStats(std::vector<double> ms) {
    FrameStats s;
    s.frames = ms.size();
    if (ms.empty()) return s;
    std::sort(ms.begin(), ms.end());
    double total = 0;
    for (double m : ms) total += m;
    s.seconds = total / 1000.0;
    s.meanMs = total / static_cast<double>(ms.size());
    const auto n = ms.size();
    s.medianMs = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
    s.p95Ms = nearestRank(ms, 95);
    s.p99Ms = nearestRank(ms, 99);
    s.maxMs = ms.back();
    return s;
}

std::string formatFrameStats(const FrameStats& s, const std::string& name) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "timedemo %s: %zu frames in %.3f s (%.1f fps)\n"
                  "  frame time ms: mean %.3f  median %.3f  p95 %.3f  p99 %.3f  max %.3f\n"
                  "timedemo name=%s frames=%zu seconds=%.4f fps=%.2f mean_ms=%.4f median_ms=%.4f p95_ms=%.4f "
                  "p99_ms=%.4f max_ms=%.4f\n",
                  name.c_str(), s.frames, s.seconds, s.seconds > 0 ? static_cast<double>(s.frames) / s.seconds : 0.0,
                  s.meanMs, s.medianMs, s.p95Ms, s.p99Ms, s.maxMs, name.c_str(), s.frames, s.seconds,
                  s.seconds > 0 ? static_cast<double>(s.frames) / s.seconds : 0.0, s.meanMs, s.medianMs, s.p95Ms,
                  s.p99Ms, s.maxMs);
    return buf;
}

std::string formatSmokeThread(const std::vector<double>& ms) {
    if (ms.empty()) return {};
    const FrameStats s = computeFrameStats(ms);
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "  smoke on the render thread ms a frame: median %.3f  p99 %.3f  max %.3f\n"
                  "timedemo-smoke-thread median_ms=%.4f p99_ms=%.4f max_ms=%.4f\n",
                  s.medianMs, s.p99Ms, s.maxMs, s.medianMs, s.p99Ms, s.maxMs);
    return buf;
}

std::string formatSegments(const std::vector<TimedemoSegment>& segments, std::size_t warmup) {
    if (segments.size() < 2) return {};
    auto steady = [warmup](const std::vector<double>& v) {
        const auto skip = static_cast<std::ptrdiff_t>(std::min(warmup, v.size()));
        return computeFrameStats({v.begin() + skip, v.end()});
    };
    std::vector<FrameStats> wall, cpu;
    for (const auto& seg : segments) {
        wall.push_back(steady(seg.frameMs));
        cpu.push_back(steady(seg.cpuMs));
    }
    std::string out = "segments (first " + std::to_string(warmup) + " frames of each left out; cpu = process CPU ms a frame):\n";
    char buf[512];
    std::snprintf(buf, sizeof buf, "  %-44s %6s %9s %8s %8s %9s %9s %9s\n", "segment", "frames", "mean ms", "median",
                  "p95", "vs first", "cpu ms", "vs first");
    out += buf;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        std::snprintf(buf, sizeof buf, "  %-44s %6zu %9.2f %8.2f %8.2f %+9.2f %9.2f %+9.2f\n", segments[i].label.c_str(),
                      wall[i].frames, wall[i].meanMs, wall[i].medianMs, wall[i].p95Ms, wall[i].meanMs - wall[0].meanMs,
                      cpu[i].meanMs, cpu[i].meanMs - cpu[0].meanMs);
        out += buf;
    }
    for (std::size_t i = 0; i < segments.size(); ++i) {
        std::snprintf(buf, sizeof buf,
                      "timedemo-segment index=%zu label=\"%s\" frames=%zu mean_ms=%.4f median_ms=%.4f p95_ms=%.4f "
                      "added_ms=%.4f cpu_ms=%.4f added_cpu_ms=%.4f\n",
                      i, segments[i].label.c_str(), wall[i].frames, wall[i].meanMs, wall[i].medianMs, wall[i].p95Ms,
                      wall[i].meanMs - wall[0].meanMs, cpu[i].meanMs, cpu[i].meanMs - cpu[0].meanMs);
        out += buf;
    }
    return out;
}

}  // namespace obscura
