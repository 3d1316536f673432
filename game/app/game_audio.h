// The game's sound: the simulation's events of each tick become positional sounds (shots, impacts,
// grenade bounces, footsteps, reloads, targets), the listener follows the camera, the volumes
// follow the settings. One way: the simulation never hears back from here. With no audio device
// the AudioSystem runs silent after one warning line, and so does this.
#pragma once

#include "audio/audio_system.h"
#include "core/vec3.h"
#include "sim/sim_events.h"

#include <string>
#include <vector>

namespace obscura {

struct Settings;

class GameAudio {
public:
    // Loads every sound in `soundDir` (throws at load time for a malformed WAV). A detonated
    // grenade hisses for `hissSeconds` (the smoke's emit time), at settings.tickRate ticks a second.
    GameAudio(const Settings& settings, const std::string& soundDir, double hissSeconds);

    void setVolumes(double master, double effects);
    // Once per simulation tick: the events of that tick.
    void onEvents(const std::vector<sim::SimEvent>& events);
    // Once per rendered frame: the camera (metres, world space) and reclaiming finished sources.
    void update(const Vec3& position, const Vec3& forward, const Vec3& up, const Vec3& velocity);
    void uiClick();
    bool available() const { return audio_.available(); }
    audio::AudioSystem& system() { return audio_; }

private:
    audio::AudioSystem audio_;
    // A detonated grenade hisses (a loop) while it emits, then fades: handle and ticks left.
    struct Hiss {
        audio::SoundHandle handle;
        int ticksLeft;
    };
    std::vector<Hiss> hisses_;
    int hissTicks_, hissFadeTicks_;
};

}  // namespace obscura
