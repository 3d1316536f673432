// Source pool: bounded, steals non-looping sources when full, stale handles are harmless.
#include "audio/audio_system.h"
#include "audio_test_util.h"

#include <gtest/gtest.h>

using namespace obscura;
using namespace obscura::audio;

namespace {
constexpr int kRate = 44100;
}

TEST(AudioPool, MoreOneShotsThanSourcesStaysBounded) {
    if (!audio_test::loopbackSupported()) GTEST_SKIP() << "ALC_SOFT_loopback not available in this OpenAL";
    AudioSettings settings;
    settings.maxSources = 8;
    AudioSystem audio(settings, kRate);
    ASSERT_TRUE(audio.available());
    audio.loadSounds(audio_test::soundsDir());
    EXPECT_EQ(audio.poolSize(), 8);
    std::vector<SoundHandle> handles;
    for (int i = 0; i < 20; ++i) {
        const SoundHandle h = audio.play("rifle_shot", {double(i), 0, -5});
        EXPECT_NE(h, 0u) << "one-shots steal a source when the pool is full";
        handles.push_back(h);
        EXPECT_LE(audio.activeSources(), settings.maxSources);
    }
    EXPECT_EQ(audio.activeSources(), settings.maxSources);
    // The earliest handles were stolen: they are stale now, and harmless.
    int stale = 0;
    for (SoundHandle h : handles) stale += audio.isPlaying(h) ? 0 : 1;
    EXPECT_EQ(stale, 20 - settings.maxSources);
    for (SoundHandle h : handles) {
        audio.stop(h);
        audio.stop(h);  // twice: second is stale
        audio.setSourcePosition(h, {1, 2, 3});
    }
    EXPECT_EQ(audio.activeSources(), 0);
    audio.stop(0);
    audio.stop(0xdeadbeef);
    audio.update();
}

TEST(AudioPool, StealsTheQuietestNotTheLoops) {
    if (!audio_test::loopbackSupported()) GTEST_SKIP() << "ALC_SOFT_loopback not available in this OpenAL";
    AudioSettings settings;
    settings.maxSources = 3;
    AudioSystem audio(settings, kRate);
    ASSERT_TRUE(audio.available());
    audio.loadSounds(audio_test::soundsDir());
    const SoundHandle loop = audio.play("smoke_hiss", {0, 0, -3}, 1.0f, 1.0f, true);
    const SoundHandle farShot = audio.play("rifle_shot", {0, 0, -80});
    const SoundHandle nearShot = audio.play("rifle_shot", {0, 0, -3});
    ASSERT_NE(loop, 0u);
    const SoundHandle next = audio.play("impact_metal", {0, 0, -4});
    EXPECT_NE(next, 0u);
    EXPECT_TRUE(audio.isPlaying(loop));
    EXPECT_TRUE(audio.isPlaying(nearShot));
    EXPECT_FALSE(audio.isPlaying(farShot)) << "the quietest one-shot (80 m away) is the one stolen";
    // Pool full of loops: nothing is stolen, play() returns 0 without error.
    audio.stop(nearShot);
    audio.stop(next);
    EXPECT_NE(audio.play("smoke_hiss", {1, 0, 0}, 1.0f, 1.0f, true), 0u);
    EXPECT_NE(audio.play("smoke_hiss", {2, 0, 0}, 1.0f, 1.0f, true), 0u);
    EXPECT_EQ(audio.play("rifle_shot", {}), 0u);
    EXPECT_EQ(audio.activeSources(), 3);
}

TEST(AudioPool, FinishedSourcesAreReclaimedByUpdate) {
    if (!audio_test::loopbackSupported()) GTEST_SKIP() << "ALC_SOFT_loopback not available in this OpenAL";
    AudioSystem audio(AudioSettings{}, kRate);
    ASSERT_TRUE(audio.available());
    audio.loadSounds(audio_test::soundsDir());
    const SoundHandle h = audio.playUi("ui_click");  // 40 ms
    const SoundHandle shot = audio.play("rifle_shot", {0, 0, -3});  // 0.7 s
    EXPECT_EQ(audio.activeSources(), 2);
    audio.renderLoopback(kRate / 5);  // 0.2 s
    audio.update();
    EXPECT_EQ(audio.activeSources(), 1);
    EXPECT_FALSE(audio.isPlaying(h));
    EXPECT_TRUE(audio.isPlaying(shot));
    audio.stop(h);  // stale: harmless
    audio.setSourcePosition(shot, {1, 0, -3});
    audio.renderLoopback(kRate);
    audio.update();
    EXPECT_EQ(audio.activeSources(), 0);
}
