#pragma once

#include <AL/alc.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace audio_test {

inline double toDb(double v) { return v > 0 ? 20.0 * std::log10(v) : -999.0; }

// RMS of one channel (0 = left, 1 = right) of interleaved stereo float, in dB FS.
inline double channelRmsDb(const std::vector<float>& lr, int channel) {
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t i = static_cast<std::size_t>(channel); i < lr.size(); i += 2, ++n) sum += double(lr[i]) * lr[i];
    return n ? toDb(std::sqrt(sum / double(n))) : -999.0;
}
inline double peakDb(const std::vector<float>& lr) {
    double p = 0;
    for (float v : lr) p = std::max(p, double(std::abs(v)));
    return toDb(p);
}

// "-23.9" or "-inf" (digital silence) for printing.
inline std::string fmtDb(double db) {
    if (db <= -998.0) return "-inf";
    char b[32];
    std::snprintf(b, sizeof b, "%.1f", db);
    return b;
}

inline bool loopbackSupported() { return alcIsExtensionPresent(nullptr, "ALC_SOFT_loopback") == ALC_TRUE; }

inline std::string soundsDir() { return std::string(OBSCURA_SOURCE_DIR) + "/media/sounds"; }

}  // namespace audio_test
