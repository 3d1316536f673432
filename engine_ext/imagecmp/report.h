// The HTML report of a failed (or passed) image comparison: per capture the reference, the
// actual frame and an amplified difference heat map side by side, the metrics against their
// tolerances, and the renderer versions each side was made with. Self-contained folder.
#pragma once

#include "imagecmp/imagecmp.h"

#include <string>
#include <vector>

namespace obscura::imagecmp {

struct ReportEntry {
    std::string name;
    std::string referencePath;  // may not exist (a missing reference)
    std::string actualPath;     // may not exist (a missing capture)
    Metrics metrics;
    Tolerance tolerance;
    std::vector<std::string> failures;  // empty = passed; also holds "missing reference" etc.
};

// Writes DIR/report.html and DIR/<name>.{reference,actual,diff}.png (characters outside
// [A-Za-z0-9_-] in a name become '_' in its file names); links are relative, so the folder can be
// moved or archived whole. `*Versions` name the renderer each side was made with. Returns the
// report's path; throws ImageError (or std::filesystem::filesystem_error) when DIR cannot be written.
std::string writeReport(const std::string& dir, const std::string& testName, const std::vector<ReportEntry>& entries,
                        const std::string& referenceVersions = "unknown", const std::string& actualVersions = "unknown");

}  // namespace obscura::imagecmp
