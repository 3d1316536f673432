// OpenAL Soft's ALC_SOFT_loopback device renders the mix into memory: no sound card needed.
// Listener at the origin facing -Z (Y up): +X is the listener's right.
#include "audio/audio_system.h"
#include "audio_test_util.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace obscura;
using namespace obscura::audio;
using audio_test::channelRmsDb;
using audio_test::fmtDb;

namespace {

constexpr int kRate = 44100;
constexpr int kFrames = kRate / 2;            // 0.5 s
constexpr double kAudibleDbfs = -40.0;        // louder channel's RMS over 0.5 s must exceed this
constexpr double kSilentDbfs = -120.0;        // nothing playing: both channels below this
constexpr double kSideDifferenceDb = 3.0;     // near side at least this much louder than the far side

struct Levels {
    double left, right, peak;
};

Levels renderShot(const Vec3& position, const Vec3& listener = {0, 0, 0}, const Vec3& forward = {0, 0, -1}) {
    AudioSystem audio(AudioSettings{}, kRate);
    EXPECT_TRUE(audio.available()) << audio.deviceDescription();
    audio.loadSounds(audio_test::soundsDir());
    audio.setListener(listener, forward, {0, 1, 0});
    EXPECT_NE(audio.play("rifle_shot", position), 0u);
    const std::vector<float> lr = audio.renderLoopback(kFrames);
    return {channelRmsDb(lr, 0), channelRmsDb(lr, 1), audio_test::peakDb(lr)};
}

}  // namespace

TEST(AudioLoopback, ShotToTheRightIsLouderOnTheRight) {
    if (!audio_test::loopbackSupported()) GTEST_SKIP() << "ALC_SOFT_loopback not available in this OpenAL";
    const Levels l = renderShot({3, 0, 0});
    std::printf("[levels] rifle_shot 3 m right (+X), 0.5 s @ %d Hz: left %s dBFS RMS, right %s dBFS RMS, peak %s dBFS\n",
                kRate, fmtDb(l.left).c_str(), fmtDb(l.right).c_str(), fmtDb(l.peak).c_str());
    EXPECT_GT(l.right, kAudibleDbfs);
    EXPECT_GE(l.right - l.left, kSideDifferenceDb);
    EXPECT_LE(l.peak, 0.0);
}

TEST(AudioLoopback, ShotToTheLeftIsLouderOnTheLeft) {
    if (!audio_test::loopbackSupported()) GTEST_SKIP() << "ALC_SOFT_loopback not available in this OpenAL";
    const Levels l = renderShot({-3, 0, 0});
    std::printf("[levels] rifle_shot 3 m left (-X), 0.5 s @ %d Hz: left %s dBFS RMS, right %s dBFS RMS, peak %s dBFS\n",
                kRate, fmtDb(l.left).c_str(), fmtDb(l.right).c_str(), fmtDb(l.peak).c_str());
    EXPECT_GT(l.left, kAudibleDbfs);
    EXPECT_GE(l.left - l.right, kSideDifferenceDb);
}

TEST(AudioLoopback, ListenerPoseIsHonoured) {
    if (!audio_test::loopbackSupported()) GTEST_SKIP() << "ALC_SOFT_loopback not available in this OpenAL";
    // Turned around (facing +Z): a source at +X is now on the listener's left.
    const Levels turned = renderShot({3, 0, 0}, {0, 0, 0}, {0, 0, 1});
    EXPECT_GE(turned.left - turned.right, kSideDifferenceDb);
    // Listener moved to x = 10 facing -Z: a source at x = 7 is on its left.
    const Levels moved = renderShot({7, 0, 0}, {10, 0, 0});
    EXPECT_GE(moved.left - moved.right, kSideDifferenceDb);
    // Straight ahead: both channels equal.
    const Levels ahead = renderShot({0, 0, -3});
    std::printf("[levels] rifle_shot 3 m ahead: left %s dBFS RMS, right %s dBFS RMS\n", fmtDb(ahead.left).c_str(),
                fmtDb(ahead.right).c_str());
    EXPECT_NEAR(ahead.left, ahead.right, 0.5);
}

TEST(AudioLoopback, SilenceWhenNothingPlays) {
    if (!audio_test::loopbackSupported()) GTEST_SKIP() << "ALC_SOFT_loopback not available in this OpenAL";
    AudioSystem audio(AudioSettings{}, kRate);
    ASSERT_TRUE(audio.available());
    audio.loadSounds(audio_test::soundsDir());
    const std::vector<float> lr = audio.renderLoopback(kFrames);
    std::printf("[levels] nothing playing: left %s dBFS, right %s dBFS\n", fmtDb(channelRmsDb(lr, 0)).c_str(),
                fmtDb(channelRmsDb(lr, 1)).c_str());
    EXPECT_LT(channelRmsDb(lr, 0), kSilentDbfs);
    EXPECT_LT(channelRmsDb(lr, 1), kSilentDbfs);
}

TEST(AudioLoopback, DistanceAttenuationAndVolumes) {
    if (!audio_test::loopbackSupported()) GTEST_SKIP() << "ALC_SOFT_loopback not available in this OpenAL";
    auto level = [](const Vec3& pos, float master, float effects, bool ui) {
        AudioSystem audio(AudioSettings{}, kRate);
        audio.loadSounds(audio_test::soundsDir());
        audio.setVolumes(master, effects);
        EXPECT_NE(ui ? audio.playUi("rifle_shot") : audio.play("rifle_shot", pos), 0u);
        const std::vector<float> lr = audio.renderLoopback(kFrames);
        return std::max(channelRmsDb(lr, 0), channelRmsDb(lr, 1));
    };
    const double near = level({0, 0, -2}, 1, 1, false);
    const double far = level({0, 0, -50}, 1, 1, false);
    std::printf("[levels] rifle_shot ahead: 2 m %.1f dBFS, 50 m %.1f dBFS (drop %.1f dB)\n", near, far, near - far);
    EXPECT_GT(far, -70.0) << "a shot 50 m away should still be faintly audible";
    EXPECT_NEAR(near - far, 20.0 * std::log10(50.0 / 2.0), 1.5);  // inverse distance, ref 2 m, rolloff 1
    const double halfEffects = level({0, 0, -2}, 1, 0.5f, false);
    EXPECT_NEAR(near - halfEffects, 6.0, 0.5);
    {  // setSourceGain: a loop faded to half is 6 dB down.
        AudioSystem audio(AudioSettings{}, kRate);
        audio.loadSounds(audio_test::soundsDir());
        const SoundHandle h = audio.play("smoke_hiss", {0, 0, -2}, 1.0f, 1.0f, true);
        const std::vector<float> full = audio.renderLoopback(kRate / 4);
        audio.setSourceGain(h, 0.5f);
        const std::vector<float> half = audio.renderLoopback(kRate / 4);
        EXPECT_NEAR(channelRmsDb(full, 0) - channelRmsDb(half, 0), 6.0, 0.7);
    }
    const double uiHalfEffects = level({}, 1, 0.5f, true);
    const double uiHalfMaster = level({}, 0.5f, 1, true);
    EXPECT_NEAR(uiHalfEffects - uiHalfMaster, 6.0, 0.5) << "UI sounds follow the master volume only";
}

TEST(AudioLoopback, UnknownSoundReturnsZero) {
    if (!audio_test::loopbackSupported()) GTEST_SKIP() << "ALC_SOFT_loopback not available in this OpenAL";
    AudioSystem audio(AudioSettings{}, kRate);
    audio.loadSounds(audio_test::soundsDir());
    EXPECT_EQ(audio.play("no_such_sound", {}), 0u);
    EXPECT_EQ(audio.play("no_such_sound", {}), 0u);  // logged once only
    EXPECT_EQ(audio.playUi("no_such_sound"), 0u);
    EXPECT_EQ(audio.activeSources(), 0);
}

TEST(AudioLoopback, RenderOnNonLoopbackThrows) {
    AudioSettings settings;
    settings.deviceName = "no such device";
    AudioSystem audio(settings);
    EXPECT_THROW(audio.renderLoopback(16), std::logic_error);
}
