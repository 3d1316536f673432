// Frame-time statistics for `--timedemo`: count, total, mean, median, p95, p99, max (ms).
// Percentiles use the nearest-rank method on the sorted frame times.
#pragma once

#include <string>
#include <vector>

namespace obscura {

struct FrameStats {
    std::size_t frames = 0;
    double seconds = 0, meanMs = 0, medianMs = 0, p95Ms = 0, p99Ms = 0, maxMs = 0;
};

FrameStats computeFrameStats(std::vector<double> frameMs);
// Human-readable lines, then one machine-readable line starting with "timedemo ".
std::string formatFrameStats(const FrameStats& s, const std::string& name);

}  // namespace obscura
