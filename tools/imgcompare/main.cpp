// obscura_imgcompare REF.png ACTUAL.png [options]: compares two frames (engine_ext/imagecmp),
// prints the metrics on one line, exits 0 when within tolerance, 1 when not (naming the failed
// metrics, writing an HTML report with --report DIR), 2 on bad input.
#include "imagecmp/report.h"

#include <boost/program_options.hpp>

#include <cmath>
#include <iostream>

namespace po = boost::program_options;
using namespace obscura::imagecmp;

int main(int argc, char** argv) {
    Tolerance t;
    std::string ref, act, reportDir, name = "compare";
    po::options_description desc("obscura_imgcompare REF.png ACTUAL.png [options]");
    desc.add_options()("help,h", "this help")
        ("min-ssim", po::value(&t.minSsim), "lowest mean luma SSIM that passes (default 0.99)")
        ("min-psnr", po::value(&t.minPsnr), "lowest PSNR in dB that passes (default 35)")
        ("max-channel-diff", po::value(&t.maxChannelDiff), "largest channel difference that passes (default 255)")
        ("pixel-threshold", po::value(&t.pixelThreshold), "a pixel counts as changed above this difference (default 16)")
        ("max-pixels-over", po::value(&t.maxPixelsOver), "changed pixels allowed (default 0)")
        ("report", po::value(&reportDir), "write an HTML report into this folder")
        ("name", po::value(&name), "name of the comparison in the report");
    po::options_description hidden;
    hidden.add_options()("ref", po::value(&ref))("actual", po::value(&act));
    po::options_description all;
    all.add(desc).add(hidden);
    po::positional_options_description pos;
    pos.add("ref", 1).add("actual", 1);
    try {
        po::variables_map vm;
        po::store(po::command_line_parser(argc, argv).options(all).positional(pos).run(), vm);
        po::notify(vm);
        if (vm.count("help")) {
            std::cout << desc;
            return 0;
        }
        if (ref.empty() || act.empty()) throw po::error("two PNG files are needed");
        if (!(t.minSsim >= -1 && t.minSsim <= 1)) throw po::error("--min-ssim must be in [-1, 1]");
        if (std::isnan(t.minPsnr)) throw po::error("--min-psnr must be a number");
        if (t.maxChannelDiff < 0 || t.maxChannelDiff > 255) throw po::error("--max-channel-diff must be in [0, 255]");
        if (t.pixelThreshold < 0 || t.pixelThreshold > 255) throw po::error("--pixel-threshold must be in [0, 255]");
        if (t.maxPixelsOver < 0) throw po::error("--max-pixels-over must not be negative");
    } catch (const po::error& e) {
        std::cerr << "obscura_imgcompare: " << e.what() << "\n" << desc;
        return 2;
    }
    try {
        const Metrics m = compare(obscura::readPng(ref), obscura::readPng(act), t.pixelThreshold);
        std::cout << formatMetrics(m) << "\n";
        const auto f = failures(m, t);
        for (const auto& s : f) std::cout << "FAIL: " << s << "\n";
        if (!reportDir.empty()) {
            ReportEntry e{name, ref, act, m, t, f};
            std::cout << "report: " << writeReport(reportDir, name, {e}) << "\n";
        }
        return f.empty() ? 0 : 1;
    } catch (const std::exception& e) {
        std::cerr << "obscura_imgcompare: " << e.what() << "\n";
        return 2;
    }
}
