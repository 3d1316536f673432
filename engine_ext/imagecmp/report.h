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

// Writes DIR/report.html and DIR/<name>.{reference,actual,diff}.png; returns the report's path.
std::string writeReport(const std::string& dir, const std::string& testName, const std::vector<ReportEntry>& entries,
                        const std::string& referenceVersions, const std::string& actualVersions);

}  // namespace obscura::imagecmp
