// Every duration the game's presentation counts in ticks, named in seconds and turned into
// ticks once, with the run's tick rate (`--tick-rate`), so an effect lasts the same wall-clock
// time at 30, 60 or 120 Hz. (The simulation itself works in seconds already: sim/combat.cpp.)
// At 60 Hz every figure below gives exactly the tick counts the game was tuned with.
#pragma once

namespace obscura {

// Headless runs with no --ticks: 5 s of game time, enough to settle physics and show the level.
constexpr double kDefaultHeadlessSeconds = 5.0;
// Sparks: a flash, not a firework.
constexpr double kSparkSeconds = 0.2;
// The muzzle flash shows for two ticks of a 60 Hz shot.
constexpr double kMuzzleFlashSeconds = 2.0 / 60.0;
// The HUD's hit marker: 1 at a hit, fading to 0 over a quarter second.
constexpr double kHitMarkerFadeSeconds = 0.25;
// A `message` centre-printed on the HUD stays 2 s (Quake's scr_centertime).
constexpr double kCentrePrintSeconds = 2.0;
// A grenade's hiss fades over the last half second of its emission.
constexpr double kHissFadeSeconds = 0.5;
// The smoke volumes step at 20 Hz: a 64^3 step costs ~6.5 ms on two cores (plus ~2.6 ms for the
// self-shadow and the texture data), four grenades four times that, and the cloud moves well
// under a cell per 50 ms, so the ray-march shows no stepping.
constexpr double kSmokeStepSeconds = 0.05;

// `seconds` as a whole number of ticks at `tickRate` (nearest; at least 1).
int ticksFor(double seconds, double tickRate);

// The figures above at one tick rate, converted once.
struct TickDurations {
    explicit TickDurations(double tickRate);
    double tickSeconds;
    long headlessTicks;
    int sparkTicks;
    int muzzleFlashTicks;
    int smokeStepTicks;
    int hissFadeTicks;
    int centrePrintTicks;
    double hitMarkerFadePerTick;  // of the marker's full strength
};

}  // namespace obscura
