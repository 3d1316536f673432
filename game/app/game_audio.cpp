// See game_audio.h.
#include "app/game_audio.h"

#include "settings.h"
#include "tick_durations.h"

#include <algorithm>

namespace obscura {

namespace {
audio::AudioSettings audioSettings(const Settings& s) {
    audio::AudioSettings a;
    a.masterVolume = static_cast<float>(s.masterVolume);
    a.effectsVolume = static_cast<float>(s.effectsVolume);
    return a;
}

const char* impactSound(sim::Surface s) {
    switch (s) {
        case sim::Surface::Target: return "impact_metal";
        case sim::Surface::Prop: return "impact_wood";
        default: return "impact_concrete";
    }
}
}  // namespace

GameAudio::GameAudio(const Settings& settings, const std::string& soundDir, double hissSeconds)
    : audio_(audioSettings(settings)), hissTicks_(ticksFor(hissSeconds, settings.tickRate)),
      hissFadeTicks_(std::min(hissTicks_, TickDurations(settings.tickRate).hissFadeTicks)) {
    audio_.loadSounds(soundDir);
}

void GameAudio::setVolumes(double master, double effects) {
    audio_.setVolumes(static_cast<float>(master), static_cast<float>(effects));
}

void GameAudio::onEvents(const std::vector<sim::SimEvent>& events) {
    if (!audio_.available()) return;
    for (auto& h : hisses_) {
        if (--h.ticksLeft <= 0) audio_.stop(h.handle);
        else if (h.ticksLeft < hissFadeTicks_) audio_.setSourceGain(h.handle, static_cast<float>(h.ticksLeft) / static_cast<float>(hissFadeTicks_));
    }
    hisses_.erase(std::remove_if(hisses_.begin(), hisses_.end(), [](const Hiss& h) { return h.ticksLeft <= 0; }), hisses_.end());
    using T = sim::SimEventType;
    for (const auto& e : events) {
        switch (e.type) {
            case T::Shot: audio_.play("rifle_shot", e.position); break;
            // Impacts a little quieter than the shot that made them, which is what the ear expects.
            case T::Impact: audio_.play(impactSound(e.surface), e.position, 0.8f); break;
            case T::TargetHit: audio_.playUi("hit_marker", 0.7f); break;
            case T::TargetDown: audio_.play("target_down", e.position); break;
            case T::TargetUp: audio_.play("target_down", e.position, 0.4f, 1.3f); break;
            case T::GrenadeThrow: audio_.play("grenade_throw", e.position, 0.7f); break;
            // Louder for harder bounces: full at 6 m/s, a tap at 1 m/s.
            case T::GrenadeBounce: {
                const double g = std::min(1.0, std::max(0.15, e.strength / 6.0));
                audio_.play("grenade_bounce", e.position, static_cast<float>(g));
                break;
            }
            case T::Footstep: {
                static const char* const kSteps[] = {"footstep_1", "footstep_2", "footstep_3", "footstep_4"};
                audio_.play(kSteps[static_cast<unsigned>(e.id) % 4u], e.position, 0.6f);
                break;
            }
            // A landing sounds like a heavy footstep, louder the harder the fall (full at 10 m/s).
            case T::Land: audio_.play("footstep_1", e.position, static_cast<float>(std::min(1.0, e.strength / 10.0)), 0.8f); break;
            case T::ReloadStart: audio_.play("reload", e.position, 0.8f); break;
            case T::DryFire: audio_.play("dry_fire", e.position); break;
            case T::GrenadeDetonate:
                if (auto h = audio_.play("smoke_hiss", e.position, 1.0f, 1.0f, true)) hisses_.push_back({h, hissTicks_});
                break;
            default: break;  // PropHit, Jump, ReloadEnd
        }
    }
}

void GameAudio::update(const Vec3& position, const Vec3& forward, const Vec3& up, const Vec3& velocity) {
    audio_.setListener(position, forward, up, velocity);
    audio_.update();
}

void GameAudio::uiClick() { audio_.playUi("ui_click", 0.6f); }

}  // namespace obscura
