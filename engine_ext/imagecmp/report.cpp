// See report.h.
#include "imagecmp/report.h"

#include <cctype>
#include <filesystem>
#include <fstream>

namespace obscura::imagecmp {

namespace fs = std::filesystem;

namespace {
// x8: a 2-level rounding difference still shows (dark red), the default 16-level pixel threshold
// is orange and 32 levels or more saturate to white; larger factors would turn noise white too.
constexpr double kHeatAmplify = 8;

std::string escape(const std::string& s) {
    std::string o;
    for (char c : s) {
        switch (c) {
            case '<': o += "&lt;"; break;
            case '>': o += "&gt;"; break;
            case '&': o += "&amp;"; break;
            case '"': o += "&quot;"; break;
            default: o += c;
        }
    }
    return o;
}
// A file stem that is safe as a file name and as a relative URL without escaping.
std::string fileStem(const std::string& name) {
    std::string o = name.empty() ? std::string("image") : name;
    for (char& c : o)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';  // no '/', no ".."
    return o;
}

// Copies `from` to `to` unless they are the same file (a report written beside its inputs).
void copyImage(const fs::path& from, const fs::path& to) {
    if (fs::exists(to) && fs::equivalent(from, to)) return;
    fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}
}  // namespace

std::string writeReport(const std::string& dir, const std::string& testName, const std::vector<ReportEntry>& entries,
                        const std::string& referenceVersions, const std::string& actualVersions) {
    fs::create_directories(dir);
    const fs::path htmlPath = fs::path(dir) / "report.html";
    std::ofstream html(htmlPath);
    if (!html) throw ImageError(htmlPath.string() + ": cannot open the report for writing");
    html << "<!doctype html><html><head><meta charset=\"utf-8\"><title>" << escape(testName)
         << "</title><style>body{font-family:sans-serif;background:#222;color:#ddd}img{max-width:32%;image-rendering:pixelated;"
            "border:1px solid #555}.fail{color:#f66}.pass{color:#6f6}td{padding:2px 8px}</style></head><body>\n";
    html << "<h1>" << escape(testName) << "</h1>\n<p>reference made on: " << escape(referenceVersions)
         << "<br>actual made on: " << escape(actualVersions) << "</p>\n";
    for (const auto& e : entries) {
        const bool pass = e.failures.empty();
        html << "<h2 class=\"" << (pass ? "pass" : "fail") << "\">" << escape(e.name) << ": " << (pass ? "pass" : "FAIL") << "</h2>\n";
        for (const auto& f : e.failures) html << "<div class=\"fail\">" << escape(f) << "</div>\n";
        html << "<table><tr><td>SSIM</td><td>" << e.metrics.ssim << "</td><td>min " << e.tolerance.minSsim << "</td></tr>"
             << "<tr><td>PSNR (dB)</td><td>" << e.metrics.psnr << "</td><td>min " << e.tolerance.minPsnr << "</td></tr>"
             << "<tr><td>max channel diff</td><td>" << e.metrics.maxChannelDiff << "</td><td>max " << e.tolerance.maxChannelDiff << "</td></tr>"
             << "<tr><td>pixels over " << e.tolerance.pixelThreshold << "</td><td>" << e.metrics.pixelsOver << "</td><td>max "
             << e.tolerance.maxPixelsOver << "</td></tr></table>\n<p>";
        const std::string stem = fileStem(e.name);
        const bool haveRef = fs::exists(e.referencePath), haveAct = fs::exists(e.actualPath);
        if (haveRef) copyImage(e.referencePath, fs::path(dir) / (stem + ".reference.png"));
        if (haveAct) copyImage(e.actualPath, fs::path(dir) / (stem + ".actual.png"));
        if (haveRef) html << "<img src=\"" << stem << ".reference.png\" title=\"reference\">";
        if (haveAct) html << "<img src=\"" << stem << ".actual.png\" title=\"actual\">";
        if (haveRef && haveAct) {
            try {
                const Image ref = readPng(e.referencePath), act = readPng(e.actualPath);
                if (ref.width == act.width && ref.height == act.height) {
                    writePng(diffHeatmap(ref, act, kHeatAmplify), (fs::path(dir) / (stem + ".diff.png")).string());
                    html << "<img src=\"" << stem << ".diff.png\" title=\"difference x8\">";
                }
            } catch (const ImageError&) {
                // An unreadable image is already listed among the failures.
            }
        }
        html << "</p><p>reference | actual | difference (x8)</p>\n";
    }
    html << "</body></html>\n";
    if (!html.flush()) throw ImageError(htmlPath.string() + ": write failed");
    return htmlPath.string();
}

}  // namespace obscura::imagecmp
