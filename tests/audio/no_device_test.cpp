// No output device: the game must keep running, silently. Each test runs in its own process under
// ctest (gtest_discover_tests), which matters for ALSOFT_DRIVERS: OpenAL Soft reads it once, when it
// first initialises.
#include "audio/audio_system.h"
#include "audio_test_util.h"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace obscura;
using namespace obscura::audio;

namespace {

void expectSilentButHarmless(AudioSystem& audio) {
    EXPECT_FALSE(audio.available());
    audio.loadSounds(audio_test::soundsDir());  // still parsed (a broken WAV is reported everywhere)
    EXPECT_TRUE(audio.hasSound("rifle_shot"));
    audio.setListener({1, 2, 3}, {0, 0, -1}, {0, 1, 0});
    EXPECT_EQ(audio.play("rifle_shot", {3, 0, 0}), 0u);
    EXPECT_EQ(audio.play("no_such_sound", {3, 0, 0}), 0u);
    EXPECT_EQ(audio.playUi("ui_click"), 0u);
    audio.setSourcePosition(0, {});
    audio.stop(0);
    audio.stop(12345);
    audio.setVolumes(0.5f, 0.5f);
    audio.update();
    EXPECT_EQ(audio.activeSources(), 0);
}

}  // namespace

TEST(AudioNoDevice, UnknownDeviceNameRunsSilent) {
    AudioSettings settings;
    settings.deviceName = "no such device";
    testing::internal::CaptureStderr();
    AudioSystem audio(settings);
    const std::string err = testing::internal::GetCapturedStderr();
    std::printf("stderr: %s", err.c_str());
    EXPECT_NE(err.find("audio: no output device ("), std::string::npos);
    EXPECT_NE(err.find("running silent"), std::string::npos);
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << "exactly one warning line";
    expectSilentButHarmless(audio);
}

TEST(AudioNoDevice, UnknownLoopbackDeviceNameRunsSilent) {
    AudioSettings settings;
    settings.deviceName = "no such device";
    AudioSystem audio(settings, 44100);
    // OpenAL Soft ignores the name of a loopback device, so this may well open; either way no throw.
    if (!audio.available()) {
        expectSilentButHarmless(audio);
        EXPECT_EQ(audio.renderLoopback(8).size(), 16u);
    }
}

TEST(AudioNoDevice, NoBackendRunsSilent) {
    // A driver list naming no real backend: OpenAL Soft then has no playback backend at all.
    ::setenv("ALSOFT_DRIVERS", "no_such_backend", 1);
    AudioSystem audio(AudioSettings{});
    ::unsetenv("ALSOFT_DRIVERS");
    std::printf("device: %s\n", audio.deviceDescription().c_str());
    expectSilentButHarmless(audio);
}
