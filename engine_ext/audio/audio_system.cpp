#include "audio/audio_system.h"

#include "audio/wav.h"

#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>

namespace obscura::audio {

namespace {

constexpr std::uint32_t kIndexBits = 12;  // up to 4095 sources
constexpr std::uint32_t kIndexMask = (1u << kIndexBits) - 1u;
constexpr int kMaxPool = static_cast<int>(kIndexMask);

// Keeping the "one warning line" promise on a machine without a sound card: probing the default
// device makes libasound print ~9 "ALSA lib ..." lines and OpenAL Soft one "AL lib: (EE)" line. Unless
// the user asked for OpenAL Soft's diagnostics (ALSOFT_LOGLEVEL set), we lower OpenAL Soft's log level
// (read once, at its initialisation) and mute libasound's error printer while the device is opened.
// libasound is the very library OpenAL Soft dlopen()s, so its handler is shared; it is restored after.
using AlsaErrorHandler = void (*)(const char*, int, const char*, int, const char*, ...);
using AlsaSetErrorHandler = int (*)(AlsaErrorHandler);
void silentAlsaError(const char*, int, const char*, int, const char*, ...) {}

class QuietDeviceProbe {
public:
    QuietDeviceProbe() {
        if (std::getenv("ALSOFT_LOGLEVEL")) return;  // the user wants the diagnostics
        ::setenv("ALSOFT_LOGLEVEL", "0", 0);
        lib_ = ::dlopen("libasound.so.2", RTLD_LAZY | RTLD_LOCAL);
        if (lib_) set_ = reinterpret_cast<AlsaSetErrorHandler>(::dlsym(lib_, "snd_lib_error_set_handler"));
        if (set_) set_(silentAlsaError);
    }
    ~QuietDeviceProbe() {
        if (set_) set_(nullptr);  // back to libasound's default printer
        if (lib_) ::dlclose(lib_);
    }
    QuietDeviceProbe(const QuietDeviceProbe&) = delete;
    QuietDeviceProbe& operator=(const QuietDeviceProbe&) = delete;

private:
    void* lib_ = nullptr;
    AlsaSetErrorHandler set_ = nullptr;
};

float clampGain(float g) { return std::isfinite(g) ? std::max(0.0f, g) : 0.0f; }

}  // namespace

struct AudioSystem::Impl {
    struct Voice {
        ALuint source = 0;
        std::uint32_t generation = 1;
        bool inUse = false;
        bool loop = false;
        bool ui = false;
        float gain = 1.0f;  // caller's gain, before volumes
        Vec3 position;
        std::uint64_t serial = 0;  // start order, for "oldest"
    };

    AudioSettings settings;
    bool loopback = false;
    ALCdevice* device = nullptr;
    ALCcontext* context = nullptr;
    LPALCRENDERSAMPLESSOFT renderSamples = nullptr;
    std::string description;
    std::vector<Voice> voices;
    std::map<std::string, ALuint> buffers;  // name -> AL buffer (0 when silent)
    std::set<std::string> warnedNames;
    bool warnedAllLooping = false;
    std::uint64_t serial = 0;
    Vec3 listener;

    bool ok() const { return context != nullptr; }
    void makeCurrent() const {
        if (context && alcGetCurrentContext() != context) alcMakeContextCurrent(context);
    }

    void goSilent(const std::string& why) {
        description = why;
        if (context) {
            if (alcGetCurrentContext() == context) alcMakeContextCurrent(nullptr);
            alcDestroyContext(context);
            context = nullptr;
        }
        if (device) {
            alcCloseDevice(device);
            device = nullptr;
        }
        std::cerr << "audio: no output device (" << why << "); running silent" << std::endl;
    }

    float effectiveGain(const Voice& v) const {
        const float vol = v.ui ? settings.masterVolume : settings.masterVolume * settings.effectsVolume;
        return clampGain(v.gain * vol);
    }

    // The gain the listener hears, estimated with the same distance model OpenAL uses.
    float audibleGain(const Voice& v) const {
        float g = effectiveGain(v);
        if (!v.ui) {
            double d = length(v.position - listener);
            d = std::clamp(d, static_cast<double>(kReferenceDistance), static_cast<double>(kMaxDistance));
            g *= static_cast<float>(kReferenceDistance / (kReferenceDistance + kRolloffFactor * (d - kReferenceDistance)));
        }
        return g;
    }

    SoundHandle handleOf(std::size_t index) const {
        return (voices[index].generation << kIndexBits) | static_cast<std::uint32_t>(index + 1);
    }
    Voice* lookup(SoundHandle h) {
        if (h == 0) return nullptr;
        const std::uint32_t idx = (h & kIndexMask);
        if (idx == 0 || idx > voices.size()) return nullptr;
        Voice& v = voices[idx - 1];
        if (!v.inUse || v.generation != (h >> kIndexBits)) return nullptr;
        return &v;
    }
    const Voice* lookup(SoundHandle h) const { return const_cast<Impl*>(this)->lookup(h); }

    void release(Voice& v) {
        alSourceStop(v.source);
        alSourcei(v.source, AL_BUFFER, 0);
        v.inUse = false;
        v.generation = (v.generation + 1) & ((1u << (32 - kIndexBits)) - 1u);
        if (v.generation == 0) v.generation = 1;
    }

    bool finished(const Voice& v) const {
        ALint state = AL_STOPPED;
        alGetSourcei(v.source, AL_SOURCE_STATE, &state);
        return state == AL_STOPPED || state == AL_INITIAL;
    }

    Voice* acquire() {
        for (Voice& v : voices)
            if (!v.inUse) return &v;
        for (Voice& v : voices)  // reclaim anything that ended since the last update()
            if (finished(v)) {
                release(v);
                return &v;
            }
        Voice* victim = nullptr;
        float victimGain = 0;
        for (Voice& v : voices) {
            if (v.loop) continue;
            const float g = audibleGain(v);
            if (!victim || g < victimGain || (g == victimGain && v.serial < victim->serial)) {
                victim = &v;
                victimGain = g;
            }
        }
        if (victim) release(*victim);
        return victim;
    }

    SoundHandle start(const std::string& name, const Vec3& position, float gain, float pitch, bool loop, bool ui) {
        if (!ok()) return 0;
        const auto it = buffers.find(name);
        if (it == buffers.end()) {
            if (warnedNames.insert(name).second)
                std::cerr << "audio: unknown sound '" << name << "' (not loaded); ignored" << std::endl;
            return 0;
        }
        makeCurrent();
        alGetError();
        Voice* v = acquire();
        if (!v) {
            if (!warnedAllLooping) {
                std::cerr << "audio: all " << voices.size() << " sources are looping; '" << name << "' dropped"
                          << std::endl;
                warnedAllLooping = true;
            }
            return 0;
        }
        v->inUse = true;
        v->loop = loop;
        v->ui = ui;
        v->gain = clampGain(gain);
        v->position = ui ? Vec3{} : position;
        v->serial = ++serial;
        const ALuint s = v->source;
        alSourcei(s, AL_BUFFER, static_cast<ALint>(it->second));
        alSourcei(s, AL_LOOPING, loop ? AL_TRUE : AL_FALSE);
        alSourcef(s, AL_PITCH, std::isfinite(pitch) ? std::clamp(pitch, 0.25f, 4.0f) : 1.0f);
        alSourcef(s, AL_GAIN, effectiveGain(*v));
        if (ui) {
            alSourcei(s, AL_SOURCE_RELATIVE, AL_TRUE);
            alSource3f(s, AL_POSITION, 0, 0, 0);
            alSourcef(s, AL_ROLLOFF_FACTOR, 0.0f);
        } else {
            alSourcei(s, AL_SOURCE_RELATIVE, AL_FALSE);
            alSource3f(s, AL_POSITION, static_cast<float>(position.x), static_cast<float>(position.y),
                       static_cast<float>(position.z));
            alSourcef(s, AL_ROLLOFF_FACTOR, kRolloffFactor);
        }
        alSource3f(s, AL_VELOCITY, 0, 0, 0);
        alSourcePlay(s);
        if (alGetError() != AL_NO_ERROR) {
            release(*v);
            return 0;
        }
        return handleOf(static_cast<std::size_t>(v - voices.data()));
    }
};

AudioSystem::AudioSystem(const AudioSettings& settings, int loopbackSampleRate) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.settings = settings;
    m.settings.maxSources = std::clamp(settings.maxSources, 1, kMaxPool);
    m.loopback = loopbackSampleRate > 0;
    const char* name = settings.deviceName.empty() ? nullptr : settings.deviceName.c_str();
    const std::string shownName = settings.deviceName.empty() ? "default device" : "'" + settings.deviceName + "'";

    std::vector<ALCint> attribs;
    if (m.loopback) {
        if (!alcIsExtensionPresent(nullptr, "ALC_SOFT_loopback")) {
            m.goSilent("ALC_SOFT_loopback not supported");
            return;
        }
        auto openLoopback =
            reinterpret_cast<LPALCLOOPBACKOPENDEVICESOFT>(alcGetProcAddress(nullptr, "alcLoopbackOpenDeviceSOFT"));
        auto formatSupported = reinterpret_cast<LPALCISRENDERFORMATSUPPORTEDSOFT>(
            alcGetProcAddress(nullptr, "alcIsRenderFormatSupportedSOFT"));
        m.renderSamples = reinterpret_cast<LPALCRENDERSAMPLESSOFT>(alcGetProcAddress(nullptr, "alcRenderSamplesSOFT"));
        if (!openLoopback || !formatSupported || !m.renderSamples) {
            m.goSilent("ALC_SOFT_loopback entry points missing");
            return;
        }
        m.device = openLoopback(name);
        if (!m.device) {
            m.goSilent("cannot open loopback device " + shownName);
            return;
        }
        if (!formatSupported(m.device, loopbackSampleRate, ALC_STEREO_SOFT, ALC_FLOAT_SOFT)) {
            m.goSilent("loopback format stereo float @" + std::to_string(loopbackSampleRate) + " Hz unsupported");
            return;
        }
        attribs = {ALC_FORMAT_CHANNELS_SOFT, ALC_STEREO_SOFT, ALC_FORMAT_TYPE_SOFT, ALC_FLOAT_SOFT,
                   ALC_FREQUENCY, loopbackSampleRate};
        m.description = "loopback " + std::to_string(loopbackSampleRate) + " Hz stereo";
    } else {
        {
            QuietDeviceProbe quiet;
            m.device = alcOpenDevice(name);
        }
        if (!m.device) {
            m.goSilent("cannot open " + shownName);
            return;
        }
        const ALCchar* opened = alcGetString(m.device, ALC_DEVICE_SPECIFIER);
        m.description = opened ? opened : "unnamed device";
    }
    // Plain stereo panning (no HRTF) unless the user's alsoft.conf says otherwise; enough sources.
    if (alcIsExtensionPresent(m.device, "ALC_SOFT_HRTF") && m.loopback) {
        attribs.push_back(ALC_HRTF_SOFT);
        attribs.push_back(ALC_FALSE);
    }
    attribs.push_back(ALC_MONO_SOURCES);
    attribs.push_back(m.settings.maxSources);
    attribs.push_back(0);
    m.context = alcCreateContext(m.device, attribs.data());
    if (!m.context || !alcMakeContextCurrent(m.context)) {
        m.goSilent("cannot create a context on " + m.description);
        return;
    }
    alGetError();
    alDistanceModel(AL_INVERSE_DISTANCE_CLAMPED);
    alSpeedOfSound(343.3f);
    for (int i = 0; i < m.settings.maxSources; ++i) {
        ALuint s = 0;
        alGenSources(1, &s);
        if (alGetError() != AL_NO_ERROR) break;  // device limit: keep what we got
        alSourcef(s, AL_REFERENCE_DISTANCE, kReferenceDistance);
        alSourcef(s, AL_ROLLOFF_FACTOR, kRolloffFactor);
        alSourcef(s, AL_MAX_DISTANCE, kMaxDistance);
        Impl::Voice v;
        v.source = s;
        m.voices.push_back(v);
    }
    if (m.voices.empty()) {
        m.goSilent("no sources available on " + m.description);
        return;
    }
    setListener({}, {0, 0, -1}, {0, 1, 0});
}

AudioSystem::~AudioSystem() {
    Impl& m = *impl_;
    if (!m.context) return;
    m.makeCurrent();
    for (auto& v : m.voices) {
        alSourceStop(v.source);
        alSourcei(v.source, AL_BUFFER, 0);
        alDeleteSources(1, &v.source);
    }
    for (auto& [name, buffer] : m.buffers)
        if (buffer) alDeleteBuffers(1, &buffer);
    alcMakeContextCurrent(nullptr);
    alcDestroyContext(m.context);
    alcCloseDevice(m.device);
}

bool AudioSystem::available() const { return impl_->ok(); }
bool AudioSystem::isLoopback() const { return impl_->loopback; }
const std::string& AudioSystem::deviceDescription() const { return impl_->description; }

void AudioSystem::loadSounds(const std::string& directory) {
    namespace fs = std::filesystem;
    Impl& m = *impl_;
    std::error_code ec;
    if (!fs::is_directory(directory, ec)) throw std::runtime_error(directory + ": not a directory");
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(directory)) {
        std::string ext = entry.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (entry.is_regular_file() && ext == ".wav") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    m.makeCurrent();
    for (const fs::path& file : files) {
        const std::string name = file.stem().string();
        if (m.buffers.count(name)) continue;  // loaded once
        WavData wav = readWav(file.string());
        if (wav.samples.empty()) throw std::runtime_error(file.string() + ": no samples");
        if (wav.channels == 2) {
            std::vector<std::int16_t> mono(wav.samples.size() / 2);
            for (std::size_t i = 0; i < mono.size(); ++i)
                mono[i] = static_cast<std::int16_t>((wav.samples[2 * i] + wav.samples[2 * i + 1]) / 2);
            wav.samples = std::move(mono);
            wav.channels = 1;
        }
        ALuint buffer = 0;
        if (m.ok()) {
            alGetError();
            alGenBuffers(1, &buffer);
            alBufferData(buffer, AL_FORMAT_MONO16, wav.samples.data(),
                         static_cast<ALsizei>(wav.samples.size() * sizeof(std::int16_t)), wav.sampleRate);
            if (alGetError() != AL_NO_ERROR) {
                alDeleteBuffers(1, &buffer);
                throw std::runtime_error(file.string() + ": OpenAL rejected the sample data");
            }
        }
        m.buffers.emplace(name, buffer);
    }
}

bool AudioSystem::hasSound(const std::string& name) const { return impl_->buffers.count(name) != 0; }

std::vector<std::string> AudioSystem::soundNames() const {
    std::vector<std::string> names;
    for (const auto& kv : impl_->buffers) names.push_back(kv.first);
    return names;
}

void AudioSystem::setListener(const Vec3& position, const Vec3& forward, const Vec3& up, const Vec3& velocity) {
    Impl& m = *impl_;
    m.listener = position;
    if (!m.ok()) return;
    m.makeCurrent();
    alListener3f(AL_POSITION, static_cast<float>(position.x), static_cast<float>(position.y),
                 static_cast<float>(position.z));
    alListener3f(AL_VELOCITY, static_cast<float>(velocity.x), static_cast<float>(velocity.y),
                 static_cast<float>(velocity.z));
    const ALfloat orientation[6] = {static_cast<float>(forward.x), static_cast<float>(forward.y),
                                    static_cast<float>(forward.z), static_cast<float>(up.x),
                                    static_cast<float>(up.y),      static_cast<float>(up.z)};
    alListenerfv(AL_ORIENTATION, orientation);
}

SoundHandle AudioSystem::play(const std::string& name, const Vec3& position, float gain, float pitch, bool loop) {
    return impl_->start(name, position, gain, pitch, loop, false);
}

SoundHandle AudioSystem::playUi(const std::string& name, float gain) {
    return impl_->start(name, {}, gain, 1.0f, false, true);
}

void AudioSystem::setSourcePosition(SoundHandle handle, const Vec3& position) {
    Impl& m = *impl_;
    Impl::Voice* v = m.lookup(handle);
    if (!v || v->ui) return;
    m.makeCurrent();
    v->position = position;
    alSource3f(v->source, AL_POSITION, static_cast<float>(position.x), static_cast<float>(position.y),
               static_cast<float>(position.z));
}

void AudioSystem::setSourceGain(SoundHandle handle, float gain) {
    Impl& m = *impl_;
    Impl::Voice* v = m.lookup(handle);
    if (!v) return;
    m.makeCurrent();
    v->gain = clampGain(gain);
    alSourcef(v->source, AL_GAIN, m.effectiveGain(*v));
}

void AudioSystem::stop(SoundHandle handle) {
    Impl& m = *impl_;
    Impl::Voice* v = m.lookup(handle);
    if (!v) return;
    m.makeCurrent();
    m.release(*v);
}

bool AudioSystem::isPlaying(SoundHandle handle) const {
    const Impl& m = *impl_;
    const Impl::Voice* v = m.lookup(handle);
    if (!v) return false;
    m.makeCurrent();
    return !m.finished(*v);
}

void AudioSystem::setVolumes(float master, float effects) {
    Impl& m = *impl_;
    m.settings.masterVolume = clampGain(master);
    m.settings.effectsVolume = clampGain(effects);
    if (!m.ok()) return;
    m.makeCurrent();
    for (const auto& v : m.voices)
        if (v.inUse) alSourcef(v.source, AL_GAIN, m.effectiveGain(v));
}

void AudioSystem::update() {
    Impl& m = *impl_;
    if (!m.ok()) return;
    m.makeCurrent();
    for (auto& v : m.voices)
        if (v.inUse && m.finished(v)) m.release(v);
}

int AudioSystem::activeSources() const {
    int n = 0;
    for (const auto& v : impl_->voices) n += v.inUse ? 1 : 0;
    return n;
}

int AudioSystem::poolSize() const { return static_cast<int>(impl_->voices.size()); }

std::vector<float> AudioSystem::renderLoopback(int frames) {
    Impl& m = *impl_;
    if (!m.loopback) throw std::logic_error("AudioSystem::renderLoopback: not a loopback device");
    std::vector<float> out(static_cast<std::size_t>(std::max(0, frames)) * 2, 0.0f);
    if (!m.ok() || frames <= 0) return out;
    m.makeCurrent();
    m.renderSamples(m.device, out.data(), frames);
    return out;
}

}  // namespace obscura::audio
