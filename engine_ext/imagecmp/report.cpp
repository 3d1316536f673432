// See report.h.
#include "imagecmp/report.h"

#include <filesystem>
#include <fstream>

namespace obscura::imagecmp {

namespace fs = std::filesystem;

namespace {
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
}  // namespace

std::string writeReport(const std::string& dir, const std::string& testName, const std::vector<ReportEntry>& entries,
                        const std::string& referenceVersions, const std::string& actualVersions) {
    fs::create_directories(dir);
    std::ofstream html(fs::path(dir) / "report.html");
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
        const bool haveRef = fs::exists(e.referencePath), haveAct = fs::exists(e.actualPath);
        if (haveRef) fs::copy_file(e.referencePath, fs::path(dir) / (e.name + ".reference.png"), fs::copy_options::overwrite_existing);
        if (haveAct) fs::copy_file(e.actualPath, fs::path(dir) / (e.name + ".actual.png"), fs::copy_options::overwrite_existing);
        if (haveRef) html << "<img src=\"" << escape(e.name) << ".reference.png\" title=\"reference\">";
        if (haveAct) html << "<img src=\"" << escape(e.name) << ".actual.png\" title=\"actual\">";
        if (haveRef && haveAct) {
            try {
                const Image ref = readPng(e.referencePath), act = readPng(e.actualPath);
                if (ref.width == act.width && ref.height == act.height) {
                    writePng(diffHeatmap(ref, act, 8), (fs::path(dir) / (e.name + ".diff.png")).string());
                    html << "<img src=\"" << escape(e.name) << ".diff.png\" title=\"difference x8\">";
                }
            } catch (const ImageError&) {
                // An unreadable image is already listed among the failures.
            }
        }
        html << "</p><p>reference | actual | difference (x8)</p>\n";
    }
    html << "</body></html>\n";
    return (fs::path(dir) / "report.html").string();
}

}  // namespace obscura::imagecmp
