// obscura_sfxgen <output-dir> [--seed N]: synthesises every game sound deterministically into
// <output-dir>/<name>.wav (22050 Hz mono 16-bit) and prints each one's length, peak and RMS.
// The committed media/sounds/ is produced by `obscura_sfxgen media/sounds`; a test checks it is current.
#include "audio/sfx_synth.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

int main(int argc, char** argv) {
    std::string dir;
    std::uint64_t seed = obscura::audio::kSfxSeed;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--seed" && i + 1 < argc) {
            seed = std::strtoull(argv[++i], nullptr, 0);
        } else if (a == "--list") {
            for (const auto& s : obscura::audio::sfxCatalogue()) std::printf("%-16s %s\n", s.name.c_str(), s.description.c_str());
            return 0;
        } else if (a == "-h" || a == "--help" || (!a.empty() && a[0] == '-')) {
            std::fprintf(stderr, "usage: %s <output-dir> [--seed N] | --list\n", argv[0]);
            return a == "-h" || a == "--help" ? 0 : 2;
        } else {
            dir = a;
        }
    }
    if (dir.empty()) {
        std::fprintf(stderr, "usage: %s <output-dir> [--seed N] | --list\n", argv[0]);
        return 2;
    }
    try {
        for (const auto& w : obscura::audio::writeSfxSet(dir, seed))
            std::printf("%-16s %5.3f s  peak %6.1f dBFS  rms %6.1f dBFS  %s\n", w.name.c_str(), w.levels.seconds,
                        w.levels.peakDbfs, w.levels.rmsDbfs, w.path.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "obscura_sfxgen: %s\n", e.what());
        return 1;
    }
    return 0;
}
