// The game's audio: OpenAL Soft, one context, a fixed pool of sources, WAVs loaded once.
// Plain C++ (no OGRE). Positions are metres, Y up, right-handed (OGRE's convention, which is
// also OpenAL's), so they pass through unchanged.
#pragma once

#include "core/vec3.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace obscura::audio {

struct AudioSettings {
    float masterVolume = 1.0f;
    float effectsVolume = 1.0f;
    int maxSources = 32;
    std::string deviceName;  // empty = default device
};

// 0 = none. A handle carries a pool index and a generation counter, so a handle whose sound has
// finished (and whose source was reused) is recognised as stale and ignored.
using SoundHandle = std::uint32_t;

// Distance model: AL_INVERSE_DISTANCE_CLAMPED, gain = ref / (ref + rolloff * (d - ref)) with d
// clamped to [ref, max]. See README.md for the reasoning.
inline constexpr float kReferenceDistance = 2.0f;  // m: full level within ~arm's reach + a step
inline constexpr float kRolloffFactor = 1.0f;      // physical 1/r (-6 dB per doubling): 50 m -> -28 dB
inline constexpr float kMaxDistance = 120.0f;      // m: beyond this no further drop (floor -35.6 dB)

class AudioSystem {
public:
    // Opens the device (or an ALC_SOFT_loopback device when loopbackSampleRate > 0, for tests).
    // Never throws for a missing/unavailable device: available() is false, one warning line goes to
    // stderr ("audio: no output device (...); running silent") and every other call is a cheap no-op.
    explicit AudioSystem(const AudioSettings& settings, int loopbackSampleRate = 0);
    ~AudioSystem();
    AudioSystem(const AudioSystem&) = delete;
    AudioSystem& operator=(const AudioSystem&) = delete;

    bool available() const;
    bool isLoopback() const;
    const std::string& deviceDescription() const;  // the opened device's name, or why none

    // Loads every *.wav (any case) in `directory` once (name = file stem). Throws std::runtime_error naming the
    // file and the problem for a malformed WAV. WAVs are parsed even when silent, so a broken file
    // is reported the same way on machines without a sound card. Stereo files are mixed to mono
    // (3D sources must be mono to be spatialised).
    void loadSounds(const std::string& directory);
    bool hasSound(const std::string& name) const;
    std::vector<std::string> soundNames() const;  // sorted

    void setListener(const Vec3& position, const Vec3& forward, const Vec3& up, const Vec3& velocity = {});

    // 3D positional one-shot or loop from the source pool. When the pool is full the quietest
    // (estimated gain at the listener) non-looping source is stolen, oldest first on ties; if every
    // source is looping, nothing plays and 0 is returned. Unknown names: logged once per name, 0.
    SoundHandle play(const std::string& name, const Vec3& position, float gain = 1.0f, float pitch = 1.0f,
                     bool loop = false);
    // Listener-relative, unattenuated (UI clicks); scaled by the master volume only.
    SoundHandle playUi(const std::string& name, float gain = 1.0f);
    void setSourcePosition(SoundHandle handle, const Vec3& position);
    void setSourceGain(SoundHandle handle, float gain);  // e.g. fade a loop out; volumes still apply
    void stop(SoundHandle handle);
    bool isPlaying(SoundHandle handle) const;  // false for 0/stale handles

    // UI sounds use master only; effects use master * effects. Applies to playing sources too.
    void setVolumes(float master, float effects);
    void update();  // once a frame: reclaim finished sources
    int activeSources() const;
    int poolSize() const;  // sources actually allocated (<= maxSources)

    // Loopback only: render `frames` stereo frames as interleaved float (L,R,...) in [-1,1].
    // Throws std::logic_error if this system was not opened as a loopback device; returns silence
    // if the loopback device was requested but could not be opened (available() false).
    std::vector<float> renderLoopback(int frames);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace obscura::audio
