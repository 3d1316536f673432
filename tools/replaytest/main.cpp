// obscura_replaytest: one replay test of the bench. Runs the game headless on a replay script
// (twice with --runs 2, checking that hashes and captures are identical; the second run draws only
// the frames its captures read), compares every capture
// with its reference image within tolerances, and on failure writes an HTML report (reference,
// actual, amplified difference, metrics, renderer versions) and prints its path.
// With --rebaseline it copies the captures over the references instead (after a reviewed change).
//
//   obscura_replaytest --game BIN --replay FILE --references DIR --out DIR [--runs N]
//                      [--min-ssim X] [--min-psnr X] [--pixel-threshold N] [--max-pixels-over N]
//                      [--rebaseline] [-- extra game arguments]
#include "core/image.h"
#include "imagecmp/report.h"
#include "replay/replay_script.h"

#include <boost/program_options.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;
namespace po = boost::program_options;
using namespace obscura;

namespace {
struct RunResult {
    int exitCode = -1;
    std::string output;
};

std::string quote(const std::string& s) { return "'" + s + "'"; }

RunResult run(const std::string& command) {
    RunResult r;
    FILE* p = popen((command + " 2>&1").c_str(), "r");
    if (!p) return r;
    char buf[4096];
    while (std::fgets(buf, sizeof buf, p)) r.output += buf;
    const int status = pclose(p);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
    return r;
}

// Lines of the game's output that must be identical run to run.
std::string hashLines(const std::string& out) {
    std::istringstream in(out);
    std::string line, keep;
    while (std::getline(in, line))
        if (line.rfind("hash ", 0) == 0 || line.rfind("state-hash ", 0) == 0) keep += line + "\n";
    return keep;
}

std::string rendererLine(const std::string& out) {
    std::istringstream in(out);
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("renderer ", 0) == 0) return line.substr(9);
    return "unknown";
}

// The renderer line the game prints does not carry Mesa's release; the package does.
std::string mesaVersion() {
    std::string v = run("dpkg-query -W -f '${Version}' libgl1-mesa-dri").output;
    return v.empty() || v.find("no packages") != std::string::npos ? "unknown" : v;
}

std::string readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
}  // namespace

int main(int argc, char** argv) {
    std::string game, replayPath, refDir, outDir;
    int runs = 1;
    bool rebaseline = false;
    imagecmp::Tolerance tol;
    std::vector<std::string> extra;
    po::options_description desc("obscura_replaytest options");
    desc.add_options()("game", po::value(&game)->required(), "the obscura executable")
        ("replay", po::value(&replayPath)->required(), "replay script")
        ("references", po::value(&refDir)->required(), "folder of reference PNGs (<capture>.png) and VERSIONS.txt")
        ("out", po::value(&outDir)->required(), "folder for captures and the report")
        ("runs", po::value(&runs), "play the replay this many times; all must agree")
        ("min-ssim", po::value(&tol.minSsim), "")("min-psnr", po::value(&tol.minPsnr), "")
        ("pixel-threshold", po::value(&tol.pixelThreshold), "")("max-pixels-over", po::value(&tol.maxPixelsOver), "")
        ("max-channel-diff", po::value(&tol.maxChannelDiff), "")
        ("rebaseline", po::bool_switch(&rebaseline), "copy the captures over the references")
        ("extra", po::value(&extra)->multitoken(), "extra arguments for the game");
    try {
        po::variables_map vm;
        po::store(po::parse_command_line(argc, argv, desc), vm);
        po::notify(vm);
    } catch (const po::error& e) {
        std::cerr << "obscura_replaytest: " << e.what() << "\n" << desc;
        return 2;
    }
    if (std::getenv("OBSCURA_REBASELINE")) rebaseline = true;

    replay::Script script;
    try {
        script = replay::loadScript(replayPath);
    } catch (const replay::ScriptError& e) {
        std::cerr << "obscura_replaytest: " << e.what() << "\n";
        return 2;
    }
    const std::string testName = fs::path(replayPath).stem().string();
    fs::remove_all(outDir);
    std::string firstHashes, firstRenderer;
    std::vector<std::string> captureNames;
    for (const auto& c : script.commands)
        if (c.type == replay::Command::Type::Capture) captureNames.push_back(c.name);

    for (int i = 0; i < runs; ++i) {
        const fs::path dir = fs::path(outDir) / ("run" + std::to_string(i + 1));
        fs::create_directories(dir);
        std::string cmd = quote(game) + " --replay " + quote(replayPath) + " --capture-dir " + quote(dir.string()) +
                          " --log " + quote((dir / "obscura.log").string());
        for (const auto& e : extra) cmd += " " + quote(e);
        // Run 1 draws every frame, as a window would; the later ones only the frames their
        // captures read (--replay-draw captures): the same captures then also show that none
        // depends on the frames drawn before it, and the run costs the ticks, not the frames.
        if (i > 0) cmd += " --replay-draw captures";
        const RunResult r = run(cmd);
        std::ofstream(dir / "output.txt") << r.output;
        if (r.exitCode != 0) {
            std::cout << "FAIL: run " << i + 1 << " exited " << r.exitCode << ":\n" << r.output;
            return 1;
        }
        if (i == 0) {
            firstHashes = hashLines(r.output);
            firstRenderer = rendererLine(r.output) + " | Mesa " + mesaVersion();
            std::cout << firstHashes;
            continue;
        }
        // Determinism: same hashes, byte-identical captures.
        if (hashLines(r.output) != firstHashes) {
            std::cout << "FAIL: run " << i + 1 << " printed different hashes:\n" << hashLines(r.output);
            return 1;
        }
        for (const auto& name : captureNames)
            if (readFile(dir / (name + ".png")) != readFile(fs::path(outDir) / "run1" / (name + ".png"))) {
                // The simulation is exact (the hashes above). A frame may differ in a few pixels of
                // an additive effect (a spark pixel, seen once in ~4 full suites), or faintly over
                // smoke (door_button's `open`: 269 pixels by at most 9 levels, once in 3 runs; its
                // `through`: 524 by 12, once in 3 suites, where the run drawing every frame strayed
                // and the one drawing only its captures matched the reference to 7 pixels by 1): a
                // rendering race not found yet (engine_ext/frame/README.md, "Known"), on the frames
                // drawn while the smoke's worker runs. Passes: up to kRunPixels pixels by up to
                // kRunLevels, or up to a 250th of the frame by up to kRunFaintLevels; more fails.
                constexpr std::size_t kRunPixels = 8;
                constexpr int kRunLevels = 64;
                constexpr int kRunFaintLevels = 12;
                const Image a = readPng((dir / (name + ".png")).string());
                const Image b = readPng((fs::path(outDir) / "run1" / (name + ".png")).string());
                std::size_t pixels = 0;
                int worst = 0;
                if (a.rgba.size() == b.rgba.size())
                    for (std::size_t p = 0; p < a.rgba.size(); p += 4) {
                        int d = 0;
                        for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c])));
                        pixels += d > 0;
                        worst = std::max(worst, d);
                    }
                const std::size_t faintPixels = a.rgba.size() / 4 / 250;
                const bool few = pixels <= kRunPixels && worst <= kRunLevels;
                const bool faint = pixels <= faintPixels && worst <= kRunFaintLevels;
                if (a.rgba.size() == b.rgba.size() && (few || faint)) {
                    std::cout << "note: capture " << name << ": " << pixels << " pixel(s) differ between run 1 and run " << i + 1
                              << " (at most " << worst << " levels)\n";
                    continue;
                }
                std::cout << "FAIL: capture " << name << " differs between run 1 and run " << i + 1 << " (" << pixels
                          << " pixels, at most " << worst << " levels)\n";
                return 1;
            }
        std::cout << "run " << i + 1 << ": identical hashes and captures\n";
    }

    const fs::path actualDir = fs::path(outDir) / "run1";
    if (rebaseline) {
        fs::create_directories(refDir);
        for (const auto& name : captureNames)
            fs::copy_file(actualDir / (name + ".png"), fs::path(refDir) / (name + ".png"), fs::copy_options::overwrite_existing);
        std::ofstream(fs::path(refDir) / "VERSIONS.txt") << firstRenderer << "\n";
        std::cout << "rebaselined " << captureNames.size() << " references in " << refDir << "\n";
        return 0;
    }

    const std::string refVersions = [&] {
        std::string v = readFile(fs::path(refDir) / "VERSIONS.txt");
        while (!v.empty() && v.back() == '\n') v.pop_back();
        return v.empty() ? std::string("unknown") : v;
    }();
    std::vector<imagecmp::ReportEntry> entries;
    bool ok = true;
    for (const auto& name : captureNames) {
        imagecmp::ReportEntry e{name, (fs::path(refDir) / (name + ".png")).string(), (actualDir / (name + ".png")).string(), {}, tol, {}};
        try {
            e.metrics = imagecmp::compare(readPng(e.referencePath), readPng(e.actualPath), tol.pixelThreshold);
            e.failures = imagecmp::failures(e.metrics, tol);
        } catch (const std::exception& ex) {
            e.failures.push_back(ex.what());
        }
        std::cout << name << ": " << imagecmp::formatMetrics(e.metrics) << (e.failures.empty() ? " ok" : " FAIL") << "\n";
        for (const auto& f : e.failures) std::cout << "  " << f << "\n";
        ok &= e.failures.empty();
        entries.push_back(e);
    }
    if (!ok) {
        const std::string report = imagecmp::writeReport((fs::path(outDir) / "report").string(), testName, entries, refVersions, firstRenderer);
        std::cout << "FAIL: " << testName << " differs from its references (made on: " << refVersions << ")\nreport: " << report << "\n";
        return 1;
    }
    return 0;
}
