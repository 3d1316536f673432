// Deterministic synthesis of every game sound (plain C++, no OpenAL): tools/sfxgen writes them to
// media/sounds/*.wav and the tests check they are reproducible. Randomness comes from obscura::Rng
// (PCG32), seeded per sound from a base seed and the sound's name.
#pragma once

#include "audio/wav.h"

#include <cstdint>
#include <string>
#include <vector>

namespace obscura::audio {

inline constexpr int kSfxSampleRate = 22050;
inline constexpr std::uint64_t kSfxSeed = 0x0b5c0a5a17d5eedULL;

struct SfxInfo {
    std::string name;         // file stem
    std::string description;  // how it is made, one line
    bool loop = false;        // made to loop seamlessly
};

// Every sound the game uses, in a fixed order.
const std::vector<SfxInfo>& sfxCatalogue();

// Float samples in [-1, 1] at kSfxSampleRate, mono. Throws std::invalid_argument for an unknown name.
std::vector<float> synthesizeSfx(const std::string& name, std::uint64_t seed = kSfxSeed);
// Rounds to 16-bit PCM (clamped; the synthesiser normalises below full scale, so nothing clips).
std::vector<std::int16_t> toPcm16(const std::vector<float>& samples);
WavData synthesizeSfxWav(const std::string& name, std::uint64_t seed = kSfxSeed);

struct SfxLevels {
    double peakDbfs = -999;  // of the 16-bit samples, relative to 32767
    double rmsDbfs = -999;
    double seconds = 0;
};
SfxLevels measureLevels(const std::vector<std::int16_t>& samples, int sampleRate = kSfxSampleRate);

// Writes <dir>/<name>.wav for every catalogue entry (creating dir); returns the levels per sound.
struct SfxWritten {
    std::string name;
    std::string path;
    SfxLevels levels;
};
std::vector<SfxWritten> writeSfxSet(const std::string& directory, std::uint64_t seed = kSfxSeed);

}  // namespace obscura::audio
