// Minimal RIFF/WAVE reader and writer for the game's sounds: integer PCM only
// (8- or 16-bit, mono or stereo). Plain C++, no OpenAL, unit-tested.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace obscura::audio {

struct WavData {
    int sampleRate = 22050;
    int channels = 1;                    // 1 or 2; samples are interleaved when 2
    std::vector<std::int16_t> samples;   // 8-bit files are widened to 16-bit on read

    int frames() const { return channels > 0 ? static_cast<int>(samples.size()) / channels : 0; }
    double seconds() const { return sampleRate > 0 ? static_cast<double>(frames()) / sampleRate : 0.0; }
};

// Serialises 16-bit PCM (canonical 44-byte header: RIFF, "fmt " (16 bytes), "data").
std::vector<std::uint8_t> encodeWav(const WavData& wav);
// Parses a WAV image. Throws std::runtime_error("<name>: <problem>") for anything malformed or
// unsupported (not RIFF/WAVE, truncated header or data, non-PCM format, odd bit depth, ...).
WavData decodeWav(const std::vector<std::uint8_t>& bytes, const std::string& nameForErrors);

// File versions; errors name the path ("<path>: <problem>").
void writeWav(const std::string& path, const WavData& wav);
WavData readWav(const std::string& path);

}  // namespace obscura::audio
