#include "audio/wav.h"
#include "audio/audio_system.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

#include <unistd.h>

using namespace obscura::audio;
namespace fs = std::filesystem;

namespace {

fs::path tempDir(const std::string& name) {
    const fs::path p = fs::temp_directory_path() / ("obscura_audio_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

void writeBytes(const fs::path& p, const std::vector<std::uint8_t>& b) {
    std::ofstream f(p, std::ios::binary);
    f.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(AudioWav, RoundTrip) {
    WavData w;
    w.sampleRate = 22050;
    w.channels = 1;
    for (int i = 0; i < 1000; ++i) w.samples.push_back(static_cast<std::int16_t>((i * 977) % 65536 - 32768));
    w.samples.push_back(32767);
    w.samples.push_back(-32768);
    const fs::path dir = tempDir("roundtrip");
    writeWav((dir / "a.wav").string(), w);
    EXPECT_EQ(fs::file_size(dir / "a.wav"), 44u + 2u * w.samples.size());
    const WavData r = readWav((dir / "a.wav").string());
    EXPECT_EQ(r.sampleRate, 22050);
    EXPECT_EQ(r.channels, 1);
    EXPECT_EQ(r.samples, w.samples);

    w.channels = 2;
    w.sampleRate = 48000;
    const WavData s = decodeWav(encodeWav(w), "stereo");
    EXPECT_EQ(s.channels, 2);
    EXPECT_EQ(s.sampleRate, 48000);
    EXPECT_EQ(s.samples, w.samples);
    EXPECT_EQ(s.frames(), 501);
    fs::remove_all(dir);
}

TEST(AudioWav, SkipsUnknownChunksAndReads8Bit) {
    std::vector<std::uint8_t> b = {'R', 'I', 'F', 'F', 0, 0, 0, 0, 'W', 'A', 'V', 'E',
                                   'L', 'I', 'S', 'T', 3, 0, 0, 0, 'x', 'y', 'z', 0,  // odd size + pad byte
                                   'f', 'm', 't', ' ', 16, 0, 0, 0, 1, 0, 1, 0, 0x22, 0x56, 0, 0,
                                   0x22, 0x56, 0, 0, 1, 0, 8, 0, 'd', 'a', 't', 'a', 3, 0, 0, 0, 128, 255, 0};
    const WavData w = decodeWav(b, "eight");
    EXPECT_EQ(w.sampleRate, 22050);
    ASSERT_EQ(w.samples.size(), 3u);
    EXPECT_EQ(w.samples[0], 0);
    EXPECT_EQ(w.samples[1], 127 * 256);
    EXPECT_EQ(w.samples[2], -128 * 256);
}

TEST(AudioWav, MalformedFilesNameTheFileAndTheProblem) {
    WavData w;
    w.samples.assign(100, 1000);
    const std::vector<std::uint8_t> good = encodeWav(w);
    const fs::path dir = tempDir("malformed");

    struct Case {
        std::string file, expect;
        std::vector<std::uint8_t> bytes;
    };
    std::vector<Case> cases;
    cases.push_back({"truncated_header.wav", "truncated header", {good.begin(), good.begin() + 8}});
    cases.push_back({"truncated_fmt.wav", "truncated header", {good.begin(), good.begin() + 30}});
    cases.push_back({"truncated_data.wav", "truncated data", {good.begin(), good.end() - 10}});
    auto notRiff = good;
    notRiff[0] = 'X';
    cases.push_back({"not_riff.wav", "not a RIFF file", notRiff});
    auto floatFmt = good;
    floatFmt[20] = 3;  // IEEE float
    cases.push_back({"float.wav", "unsupported format tag 3", floatFmt});
    auto bits24 = good;
    bits24[34] = 24;
    cases.push_back({"bits24.wav", "unsupported bit depth 24", bits24});
    auto sixChannels = good;
    sixChannels[22] = 6;
    cases.push_back({"six.wav", "unsupported channel count 6", sixChannels});

    for (const Case& c : cases) {
        const fs::path p = dir / c.file;
        writeBytes(p, c.bytes);
        const std::string err = errorOf([&] { readWav(p.string()); });
        EXPECT_NE(err.find(p.string()), std::string::npos) << c.file << ": " << err;
        EXPECT_NE(err.find(c.expect), std::string::npos) << c.file << ": " << err;
    }
    EXPECT_NE(errorOf([&] { readWav((dir / "missing.wav").string()); }).find("missing.wav"), std::string::npos);

    // AudioSystem::loadSounds reports the broken file too (even with no device at all).
    const fs::path soundDir = tempDir("malformed_dir");
    writeWav((soundDir / "fine.wav").string(), w);
    writeBytes(soundDir / "broken.wav", cases[4].bytes);
    AudioSettings settings;
    settings.deviceName = "no such device";
    AudioSystem audio(settings);
    const std::string err = errorOf([&] { audio.loadSounds(soundDir.string()); });
    EXPECT_NE(err.find("broken.wav"), std::string::npos) << err;
    EXPECT_NE(err.find("unsupported format"), std::string::npos) << err;
    fs::remove_all(dir);
    fs::remove_all(soundDir);
}
