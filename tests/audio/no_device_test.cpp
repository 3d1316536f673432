// No output device: the game must keep running, silently.
// ALSOFT_DRIVERS is read once, when OpenAL Soft first initialises in a process, so the tests that set
// it run their body in a fresh child process (gtest's "threadsafe" death-test style re-executes the
// test binary for the child), whatever ran before in this one.
#include "audio/audio_system.h"
#include "audio_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

using namespace obscura;
using namespace obscura::audio;

namespace {

// Exercises every call on a silent system; returns "" or what went wrong.
std::string silentButHarmless(AudioSystem& audio) {
    std::ostringstream err;
    if (audio.available()) err << "available() is true; ";
    audio.loadSounds(audio_test::soundsDir());  // still parsed (a broken WAV is reported everywhere)
    if (!audio.hasSound("rifle_shot")) err << "sounds not listed; ";
    audio.setListener({1, 2, 3}, {0, 0, -1}, {0, 1, 0});
    if (audio.play("rifle_shot", {3, 0, 0}) != 0) err << "play() != 0; ";
    if (audio.play("no_such_sound", {3, 0, 0}) != 0) err << "play(unknown) != 0; ";
    if (audio.playUi("ui_click") != 0) err << "playUi() != 0; ";
    audio.setSourcePosition(0, {});
    audio.stop(0);
    audio.stop(12345);
    audio.setVolumes(0.5f, 0.5f);
    audio.update();
    if (audio.activeSources() != 0) err << "activeSources() != 0; ";
    return err.str();
}

// Runs `body` in a fresh process with ALSOFT_DRIVERS=drivers; the child exits 0 when body returns "".
#define EXPECT_IN_FRESH_PROCESS(drivers, body, stderrRegex)                                  \
    do {                                                                                      \
        GTEST_FLAG_SET(death_test_style, "threadsafe");                                       \
        EXPECT_EXIT(                                                                          \
            {                                                                                 \
                ::setenv("ALSOFT_DRIVERS", drivers, 1);                                       \
                const std::string problem = (body)();                                         \
                std::fprintf(stderr, "child: %s\n", problem.empty() ? "ok" : problem.c_str()); \
                std::fflush(stderr);                                                          \
                std::_Exit(problem.empty() ? 0 : 1);                                          \
            },                                                                                \
            testing::ExitedWithCode(0), stderrRegex);                                         \
    } while (0)

}  // namespace

TEST(AudioNoDevice, UnknownDeviceNameRunsSilent) {
    AudioSettings settings;
    settings.deviceName = "no such device";
    testing::internal::CaptureStderr();
    AudioSystem audio(settings);
    const std::string err = testing::internal::GetCapturedStderr();
    std::printf("stderr: %s", err.c_str());
    EXPECT_NE(err.find("audio: no output device (cannot open 'no such device'); running silent\n"), std::string::npos);
    std::size_t ours = 0;
    for (std::size_t p = err.find("audio:"); p != std::string::npos; p = err.find("audio:", p + 1)) ++ours;
    EXPECT_EQ(ours, 1u) << "exactly one warning line of ours";
    EXPECT_EQ(silentButHarmless(audio), "");
}

TEST(AudioNoDevice, NoBackendRunsSilent) {
    // A driver list naming no real backend: OpenAL Soft 1.19 then has no playback backend at all.
    EXPECT_IN_FRESH_PROCESS("no_such_backend", [] {
        AudioSystem audio(AudioSettings{});
        return silentButHarmless(audio);
    }, "audio: no output device \\(cannot open default device\\); running silent(.|\n)*child: ok");
}

TEST(AudioNoDevice, DefaultAlsaDeviceWarnsWithOneLine) {
    // The headless case the game meets in CI: OpenAL Soft's ALSA backend, no card. libasound and
    // OpenAL Soft would print ~10 lines of their own; AudioSystem keeps it to its one warning line.
    EXPECT_IN_FRESH_PROCESS("alsa", [] {
        ::unsetenv("ALSOFT_LOGLEVEL");
        testing::internal::CaptureStderr();
        std::string problem;
        {
            AudioSystem audio(AudioSettings{});
            if (!audio.available()) problem = silentButHarmless(audio);
        }
        const std::string err = testing::internal::GetCapturedStderr();
        std::fprintf(stderr, "captured: [%s]\n", err.c_str());
        const auto lines = std::count(err.begin(), err.end(), '\n');
        if (err.empty()) return problem;  // a real ALSA device opened: nothing to say
        if (lines != 1 || err.rfind("audio: no output device (", 0) != 0)
            problem += "expected exactly one 'audio: no output device' line; ";
        return problem;
    }, "child: ok");
}

TEST(AudioNoDevice, NullBackendPlaysWithoutSoundCard) {
    // ALSOFT_DRIVERS=null: OpenAL Soft's null backend mixes into nothing; the game runs "with audio".
    EXPECT_IN_FRESH_PROCESS("null", [] {
        std::ostringstream err;
        AudioSystem audio(AudioSettings{});
        if (!audio.available()) return std::string("null backend unavailable: ") + audio.deviceDescription();
        audio.loadSounds(audio_test::soundsDir());
        const SoundHandle h = audio.play("rifle_shot", {3, 0, 0});
        if (h == 0) err << "play() returned 0; ";
        if (audio.activeSources() != 1) err << "activeSources() != 1; ";
        audio.update();
        audio.stop(h);
        audio.stop(h);
        if (audio.activeSources() != 0) err << "activeSources() != 0 after stop; ";
        return err.str();
    }, "child: ok");
}
