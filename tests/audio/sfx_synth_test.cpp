// The synthesiser: deterministic, every sound non-silent and unclipped, the hiss loops seamlessly,
// and the committed media/sounds/*.wav are exactly what obscura_sfxgen makes today.
#include "audio/sfx_synth.h"
#include "audio_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include <unistd.h>

using namespace obscura::audio;
namespace fs = std::filesystem;

namespace {

std::vector<char> fileBytes(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(AudioSynth, CatalogueHasEveryGameSound) {
    std::set<std::string> names;
    for (const auto& s : sfxCatalogue()) names.insert(s.name);
    for (const char* n : {"rifle_shot", "impact_concrete", "impact_metal", "impact_wood", "grenade_bounce",
                          "grenade_throw", "smoke_hiss", "footstep_1", "footstep_2", "footstep_3", "footstep_4",
                          "reload", "dry_fire", "target_down", "ui_click", "hit_marker"})
        EXPECT_TRUE(names.count(n)) << n;
    EXPECT_EQ(names.size(), sfxCatalogue().size()) << "no duplicate names";
    EXPECT_THROW(synthesizeSfx("no_such_sound"), std::invalid_argument);
}

TEST(AudioSynth, DeterministicPerSeed) {
    for (const auto& s : sfxCatalogue()) {
        const std::vector<float> a = synthesizeSfx(s.name, 1234);
        const std::vector<float> b = synthesizeSfx(s.name, 1234);
        EXPECT_EQ(a, b) << s.name;
        EXPECT_NE(a, synthesizeSfx(s.name, 1235)) << s.name << ": the seed must matter";
    }
    EXPECT_NE(synthesizeSfx("footstep_1"), synthesizeSfx("footstep_2")) << "footstep variations differ";
}

TEST(AudioSynth, NonSilentNotClippedShort) {
    for (const auto& s : sfxCatalogue()) {
        const WavData w = synthesizeSfxWav(s.name);
        const SfxLevels l = measureLevels(w.samples);
        std::printf("[levels] %-16s %5.3f s  peak %6.1f dBFS  rms %6.1f dBFS\n", s.name.c_str(), l.seconds, l.peakDbfs,
                    l.rmsDbfs);
        EXPECT_EQ(w.sampleRate, 22050);
        EXPECT_EQ(w.channels, 1);
        EXPECT_LE(l.peakDbfs, -0.5) << s.name << ": headroom, never clipped";
        EXPECT_GT(l.peakDbfs, -12.5) << s.name;
        EXPECT_GT(l.rmsDbfs, -45.0) << s.name << ": non-silent";
        EXPECT_LE(l.seconds, 2.01) << s.name;
        EXPECT_GE(l.seconds, 0.03) << s.name;
        const auto full = std::count_if(w.samples.begin(), w.samples.end(),
                                        [](std::int16_t v) { return v >= 32767 || v <= -32767; });
        EXPECT_EQ(full, 0) << s.name;
        if (!s.loop) {  // one-shots fade to silence: no click when the buffer ends
            EXPECT_LE(std::abs(int(w.samples.back())), 1) << s.name;
        }
    }
}

TEST(AudioSynth, HissLoopSeamIsContinuous) {
    const std::vector<float> x = synthesizeSfx("smoke_hiss");
    ASSERT_EQ(x.size(), 44100u) << "2.0 s at 22050 Hz";
    // Sample-to-sample steps inside the loop vs. the step across the seam (last -> first sample).
    std::vector<double> steps;
    for (std::size_t i = 1; i < x.size(); ++i) steps.push_back(std::abs(double(x[i]) - x[i - 1]));
    std::sort(steps.begin(), steps.end());
    const double seam = std::abs(double(x.front()) - x.back());
    const double p99 = steps[steps.size() * 99 / 100];
    std::printf("[seam] |x[0]-x[N-1]| = %.4f, median step %.4f, 99th percentile step %.4f\n", seam,
                steps[steps.size() / 2], p99);
    EXPECT_LE(seam, p99) << "the wrap-around step is no bigger than an ordinary one";
    // Loudness either side of the seam matches (no level jump): RMS of 50 ms before vs after.
    auto rms = [&](std::size_t from, std::size_t n) {
        double s = 0;
        for (std::size_t i = from; i < from + n; ++i) s += double(x[i]) * x[i];
        return std::sqrt(s / double(n));
    };
    const std::size_t n = 1102;
    const double before = audio_test::toDb(rms(x.size() - n, n)), after = audio_test::toDb(rms(0, n));
    std::printf("[seam] RMS 50 ms before %.1f dBFS, after %.1f dBFS\n", before, after);
    EXPECT_NEAR(before, after, 1.5);
}

TEST(AudioSynth, CommittedSoundsAreUpToDate) {
    const fs::path committed = audio_test::soundsDir();
    const fs::path fresh = fs::temp_directory_path() / ("obscura_sfxgen_" + std::to_string(::getpid()));
    fs::remove_all(fresh);
    writeSfxSet(fresh.string());
    std::set<std::string> committedWavs;
    for (const auto& e : fs::directory_iterator(committed))
        if (e.path().extension() == ".wav") committedWavs.insert(e.path().filename().string());
    for (const auto& s : sfxCatalogue()) {
        const std::string file = s.name + ".wav";
        EXPECT_TRUE(committedWavs.count(file)) << file << " missing: run obscura_sfxgen media/sounds";
        EXPECT_TRUE(fileBytes(committed / file) == fileBytes(fresh / file))
            << file << " differs from a fresh synthesis: run obscura_sfxgen media/sounds and commit";
        committedWavs.erase(file);
    }
    for (const auto& extra : committedWavs) ADD_FAILURE() << "media/sounds/" << extra << " is not made by obscura_sfxgen";
    fs::remove_all(fresh);
}
