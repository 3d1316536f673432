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

// A timedemo split where its script changes settings (`set` lines): the frames after each change,
// labelled with what was set, so one run compares e.g. every AO mode on the same view.
struct TimedemoSegment {
    std::string label;           // "ssao=horizon ssao-samples=8", or "start"
    std::vector<double> frameMs;
    // CPU time the whole process (llvmpipe's rasteriser threads included) spent per frame: on a
    // machine shared with other jobs it measures a software renderer's work where wall time cannot.
    std::vector<double> cpuMs;
};
// A table of the segments (the first `warmup` frames of each left out: a new compositor compiles
// its shaders there), each with its mean wall and CPU time and their differences from the first
// segment's, then one machine-readable "timedemo-segment " line each. Empty for one segment.
std::string formatSegments(const std::vector<TimedemoSegment>& segments, std::size_t warmup);
// The smoke's work on the render thread a frame (ms; smoke/smoke_pipeline.h): its median, p99 and
// max over the frames, a line each way (human, then "timedemo-smoke-thread "); empty if none.
std::string formatSmokeThread(const std::vector<double>& ms);
// Human-readable lines, then one machine-readable line starting with "timedemo ".
std::string formatFrameStats(const FrameStats& s, const std::string& name);

}  // namespace obscura
