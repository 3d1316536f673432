#include "audio/sfx_synth.h"

#include "core/rng.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <stdexcept>

namespace obscura::audio {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRate = kSfxSampleRate;

using Sig = std::vector<double>;

int samplesFor(double seconds) { return static_cast<int>(std::lround(seconds * kRate)); }
double dbToGain(double db) { return std::pow(10.0, db / 20.0); }

std::uint64_t fnv1a(const std::string& s) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (unsigned char c : s) {
        h ^= c;
        h *= 0x100000001b3ULL;
    }
    return h;
}

// RBJ audio-EQ-cookbook biquad (direct form I). Coefficients may be changed per sample (sweeps).
struct Biquad {
    enum Kind { LowPass, HighPass, BandPass };
    double b0 = 1, b1 = 0, b2 = 0, a1 = 0, a2 = 0;
    double x1 = 0, x2 = 0, y1 = 0, y2 = 0;

    Biquad() = default;
    Biquad(Kind kind, double fc, double q) { set(kind, fc, q); }

    void set(Kind kind, double fc, double q) {
        fc = std::clamp(fc, 10.0, kRate * 0.45);
        const double w0 = 2.0 * kPi * fc / kRate;
        const double cw = std::cos(w0), alpha = std::sin(w0) / (2.0 * q);
        const double a0 = 1.0 + alpha;
        double nb0, nb1, nb2;
        switch (kind) {
        case LowPass: nb0 = (1.0 - cw) / 2.0; nb1 = 1.0 - cw; nb2 = (1.0 - cw) / 2.0; break;
        case HighPass: nb0 = (1.0 + cw) / 2.0; nb1 = -(1.0 + cw); nb2 = (1.0 + cw) / 2.0; break;
        default: nb0 = alpha; nb1 = 0.0; nb2 = -alpha; break;  // band-pass, 0 dB peak
        }
        b0 = nb0 / a0; b1 = nb1 / a0; b2 = nb2 / a0;
        a1 = -2.0 * cw / a0; a2 = (1.0 - alpha) / a0;
    }
    double operator()(double x) {
        const double y = b0 * x + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
        x2 = x1; x1 = x; y2 = y1; y1 = y;
        return y;
    }
};

struct Filter {
    Biquad::Kind kind = Biquad::LowPass;
    double fc = 0;  // 0 = no filter (white)
    double q = 0.7071;
    int stages = 1;
};

double noiseSample(Rng& rng) { return rng.uniform01d() * 2.0 - 1.0; }

void normalizePeak(Sig& s, double peak = 1.0) {
    double m = 0;
    for (double v : s) m = std::max(m, std::abs(v));
    if (m > 0)
        for (double& v : s) v *= peak / m;
}

// Attack (linear) then exponential decay with time constant tau.
double envelope(double t, double attack, double tau) {
    if (t < 0) return 0;
    if (t < attack) return t / attack;
    return std::exp(-(t - attack) / tau);
}

// Filtered noise burst, peak-normalised to 1. A short pre-roll settles the filter.
Sig noiseBurst(Rng& rng, double seconds, const Filter& f, double attack, double tau) {
    const int n = samplesFor(seconds), pre = 64;
    std::vector<Biquad> stages;
    if (f.fc > 0)
        for (int i = 0; i < f.stages; ++i) stages.emplace_back(f.kind, f.fc, f.q);
    Sig s(static_cast<std::size_t>(n));
    for (int i = -pre; i < n; ++i) {
        double x = noiseSample(rng);
        for (auto& b : stages) x = b(x);
        if (i >= 0) s[static_cast<std::size_t>(i)] = x * envelope(i / kRate, attack, tau);
    }
    normalizePeak(s);
    return s;
}

// Sine whose frequency glides from f0 to f1 with time constant sweepTau (0 = fixed f0).
Sig tone(double seconds, double f0, double f1, double sweepTau, double attack, double tau, double phase = 0) {
    const int n = samplesFor(seconds);
    Sig s(static_cast<std::size_t>(n));
    double ph = phase;
    for (int i = 0; i < n; ++i) {
        const double t = i / kRate;
        const double f = sweepTau > 0 ? f1 + (f0 - f1) * std::exp(-t / sweepTau) : f0;
        s[static_cast<std::size_t>(i)] = std::sin(ph) * envelope(t, attack, tau);
        ph += 2.0 * kPi * f / kRate;
        if (ph > 2.0 * kPi) ph -= 2.0 * kPi;
    }
    return s;
}

void mixInto(Sig& dst, const Sig& src, double gain, double startSeconds = 0) {
    const int off = samplesFor(startSeconds);
    for (std::size_t i = 0; i < src.size(); ++i) {
        const std::size_t j = static_cast<std::size_t>(off) + i;
        if (j >= dst.size()) break;
        dst[j] += gain * src[i];
    }
}

// Final touch for one-shots: a half-cosine fade over the last 15 % (at least 4 ms), so a ringing
// tail dies away instead of being cut (no click at the buffer end), then peak to `peakDb` dBFS.
Sig finish(Sig s, double peakDb) {
    const int n = static_cast<int>(s.size());
    const int fade = std::min(std::max(samplesFor(0.004), n * 15 / 100), n);
    for (int i = 0; i < fade; ++i)
        s[static_cast<std::size_t>(n - 1 - i)] *= 0.5 - 0.5 * std::cos(kPi * static_cast<double>(i) / fade);
    normalizePeak(s, dbToGain(peakDb));
    return s;
}

// Inharmonic struck-plate partials (ratios of a free square plate, roughly).
Sig metalPartials(Rng& rng, double seconds, double base, const std::vector<double>& ratios,
                  const std::vector<double>& amps, const std::vector<double>& taus) {
    Sig s(static_cast<std::size_t>(samplesFor(seconds)), 0.0);
    for (std::size_t k = 0; k < ratios.size(); ++k) {
        const double f = base * ratios[k] * (1.0 + rng.uniform01d() * 0.02 - 0.01);
        mixInto(s, tone(seconds, f, f, 0, 0.0004, taus[k], rng.uniform01d() * 2 * kPi), amps[k]);
    }
    normalizePeak(s);
    return s;
}

// A mechanical click: band-passed noise snap plus two short resonances.
Sig mechClick(Rng& rng, double seconds, double f) {
    Sig s(static_cast<std::size_t>(samplesFor(seconds)), 0.0);
    mixInto(s, noiseBurst(rng, seconds, {Biquad::BandPass, f * 1.8, 2.0, 1}, 0.0002, 0.0025), 1.0);
    mixInto(s, tone(seconds, f, f, 0, 0.0003, 0.012, rng.uniform01d() * 2 * kPi), 0.6);
    mixInto(s, tone(seconds, f * 2.7, f * 2.7, 0, 0.0003, 0.006, rng.uniform01d() * 2 * kPi), 0.3);
    normalizePeak(s);
    return s;
}

// Noise through a band-pass that rises and falls (slides, whooshes), with a sin^2 swell.
Sig slide(Rng& rng, double seconds, double fLow, double fHigh, double q) {
    const int n = samplesFor(seconds);
    Sig s(static_cast<std::size_t>(n));
    Biquad bp(Biquad::BandPass, fLow, q);
    for (int i = 0; i < n; ++i) {
        const double u = static_cast<double>(i) / n;
        const double shape = std::pow(std::sin(kPi * std::pow(u, 0.8)), 2.0);
        if ((i & 15) == 0) bp.set(Biquad::BandPass, fLow + (fHigh - fLow) * shape, q);
        s[static_cast<std::size_t>(i)] = bp(noiseSample(rng)) * shape;
    }
    normalizePeak(s);
    return s;
}

Sig rifleShot(Rng& rng) {
    const double len = 0.7;
    Sig s(static_cast<std::size_t>(samplesFor(len)), 0.0);
    mixInto(s, noiseBurst(rng, len, {Biquad::HighPass, 1500, 0.7071, 2}, 0.0003, 0.006), 1.0);   // crack
    mixInto(s, noiseBurst(rng, len, {Biquad::BandPass, 700, 0.8, 1}, 0.0005, 0.025), 0.8);       // body
    mixInto(s, tone(len, 110, 45, 0.03, 0.001, 0.07), 0.9);                                      // thump
    Sig tail = noiseBurst(rng, len, {Biquad::LowPass, 900, 0.7071, 2}, 0.005, 0.18);             // decaying tail
    mixInto(s, tail, 0.35);
    mixInto(s, noiseBurst(rng, len - 0.09, {Biquad::LowPass, 600, 0.7071, 2}, 0.004, 0.12), 0.18, 0.09);  // slap echo
    return finish(s, -1.0);
}

Sig impactConcrete(Rng& rng) {
    const double len = 0.35;
    Sig s(static_cast<std::size_t>(samplesFor(len)), 0.0);
    mixInto(s, noiseBurst(rng, len, {Biquad::BandPass, 2500, 1.2, 1}, 0.0002, 0.010), 1.0);
    mixInto(s, tone(len, 160, 90, 0.02, 0.0005, 0.025), 0.5);
    mixInto(s, noiseBurst(rng, len, {Biquad::HighPass, 1500, 0.7071, 1}, 0.002, 0.06), 0.15);  // grit
    for (int k = 0; k < 6; ++k) {  // falling debris
        const double t0 = 0.02 + rng.uniform01d() * 0.18;
        const double f = 3000 + rng.uniform01d() * 3000;
        const double w = (0.08 + rng.uniform01d() * 0.17) * (1.0 - t0 * 2.5);
        mixInto(s, noiseBurst(rng, 0.03, {Biquad::BandPass, f, 2.0, 1}, 0.0002, 0.003), w, t0);
    }
    return finish(s, -3.0);
}

Sig impactMetal(Rng& rng) {
    const double len = 0.8;
    Sig s(static_cast<std::size_t>(samplesFor(len)), 0.0);
    const double base = 480 + rng.uniform01d() * 80;
    mixInto(s, metalPartials(rng, len, base, {1.0, 2.32, 4.25, 6.63, 9.38}, {1, 0.7, 0.5, 0.35, 0.2},
                             {0.35, 0.25, 0.15, 0.10, 0.06}), 1.0);
    mixInto(s, noiseBurst(rng, len, {Biquad::HighPass, 3000, 0.7071, 1}, 0.0001, 0.002), 0.6);
    return finish(s, -3.0);
}

Sig impactWood(Rng& rng) {
    const double len = 0.3;
    Sig s(static_cast<std::size_t>(samplesFor(len)), 0.0);
    mixInto(s, noiseBurst(rng, len, {Biquad::BandPass, 450, 3.0, 1}, 0.0003, 0.025), 1.0);
    mixInto(s, tone(len, 190, 190, 0, 0.0005, 0.040, rng.uniform01d() * 2 * kPi), 0.6);
    mixInto(s, tone(len, 420, 420, 0, 0.0005, 0.030, rng.uniform01d() * 2 * kPi), 0.4);
    mixInto(s, tone(len, 780, 780, 0, 0.0005, 0.015, rng.uniform01d() * 2 * kPi), 0.2);
    mixInto(s, noiseBurst(rng, len, {Biquad::HighPass, 2500, 0.7071, 1}, 0.0001, 0.0015), 0.3);
    return finish(s, -3.0);
}

Sig grenadeBounce(Rng& rng) {
    const double len = 0.35;
    Sig hit(static_cast<std::size_t>(samplesFor(0.2)), 0.0);
    mixInto(hit, metalPartials(rng, 0.2, 1700 + rng.uniform01d() * 200, {1.0, 1.58, 2.71}, {1, 0.6, 0.3},
                               {0.06, 0.04, 0.025}), 1.0);
    mixInto(hit, tone(0.2, 150, 100, 0.02, 0.0005, 0.02), 0.7);
    mixInto(hit, noiseBurst(rng, 0.2, {Biquad::HighPass, 2000, 0.7071, 1}, 0.0001, 0.002), 0.4);
    Sig s(static_cast<std::size_t>(samplesFor(len)), 0.0);
    mixInto(s, hit, 1.0);
    mixInto(s, hit, 0.35, 0.12 + rng.uniform01d() * 0.02);  // small second bounce
    return finish(s, -4.0);
}

Sig grenadeThrow(Rng& rng) {
    const double len = 0.45;
    Sig s(static_cast<std::size_t>(samplesFor(len)), 0.0);
    mixInto(s, slide(rng, len, 350, 1450, 1.5), 1.0);
    mixInto(s, noiseBurst(rng, 0.15, {Biquad::LowPass, 400, 0.7071, 1}, 0.02, 0.05), 0.2);  // arm/cloth rustle
    return finish(s, -8.0);
}

// ~2 s loop: high hiss + a softer mid band, slow amplitude wobble with periods dividing the loop,
// and an equal-power crossfade of the signal's continuation into its start so the seam is seamless.
Sig smokeHiss(Rng& rng) {
    const int n = samplesFor(2.0), fade = samplesFor(0.25), pre = samplesFor(0.1);
    Biquad hp1(Biquad::HighPass, 2500, 0.7071), hp2(Biquad::HighPass, 2500, 0.7071), lp(Biquad::LowPass, 9000, 0.7071);
    Biquad mid(Biquad::BandPass, 900, 0.7);
    const double ph1 = rng.uniform01d() * 2 * kPi, ph2 = rng.uniform01d() * 2 * kPi;
    Sig x(static_cast<std::size_t>(n + fade));
    for (int i = -pre; i < n + fade; ++i) {
        const double hiss = lp(hp2(hp1(noiseSample(rng))));
        const double body = mid(noiseSample(rng));
        if (i < 0) continue;
        const double t = i / kRate;  // wobble periods 2 s and 2/3 s: identical at t and t + 2 s
        const double wobble = 1.0 + 0.12 * std::sin(2 * kPi * t / 2.0 + ph1) + 0.06 * std::sin(2 * kPi * 3 * t / 2.0 + ph2);
        x[static_cast<std::size_t>(i)] = (hiss + 0.35 * body) * wobble;
    }
    Sig s(x.begin(), x.begin() + n);
    for (int i = 0; i < fade; ++i) {
        const double u = (i + 0.5) / fade;
        const double in = std::sin(0.5 * kPi * u), out = std::cos(0.5 * kPi * u);
        s[static_cast<std::size_t>(i)] = in * x[static_cast<std::size_t>(i)] + out * x[static_cast<std::size_t>(n + i)];
    }
    normalizePeak(s, dbToGain(-9.0));
    return s;
}

Sig footstep(Rng& rng) {
    const double len = 0.22;
    Sig s(static_cast<std::size_t>(samplesFor(len)), 0.0);
    const double toe = 0.035 + rng.uniform01d() * 0.025;
    mixInto(s, noiseBurst(rng, len, {Biquad::LowPass, 250 + rng.uniform01d() * 200, 0.7071, 2}, 0.0015,
                          0.018 + rng.uniform01d() * 0.012), 1.0);  // heel
    mixInto(s, tone(len, 70 + rng.uniform01d() * 30, 55, 0.02, 0.002, 0.03, rng.uniform01d() * 2 * kPi), 0.5);
    mixInto(s, noiseBurst(rng, len - toe, {Biquad::LowPass, 500 + rng.uniform01d() * 300, 0.7071, 2}, 0.001, 0.015),
            0.35 + rng.uniform01d() * 0.2, toe);  // toe
    const double gritF = 2500 + rng.uniform01d() * 1500;
    mixInto(s, noiseBurst(rng, 0.05, {Biquad::BandPass, gritF, 1.0, 1}, 0.0005, 0.008), 0.12);
    mixInto(s, noiseBurst(rng, 0.05, {Biquad::BandPass, gritF, 1.0, 1}, 0.0005, 0.008), 0.10, toe);
    return finish(s, -9.0 - rng.uniform01d() * 2.0);
}

Sig reload(Rng& rng) {
    const double len = 0.8;
    Sig s(static_cast<std::size_t>(samplesFor(len)), 0.0);
    mixInto(s, mechClick(rng, 0.06, 2000), 0.6, 0.03);         // magazine release
    mixInto(s, slide(rng, 0.12, 800, 1600, 1.0), 0.25, 0.08);  // magazine out
    mixInto(s, mechClick(rng, 0.06, 1400), 1.0, 0.38);         // magazine in
    mixInto(s, tone(0.06, 180, 140, 0.02, 0.0005, 0.015), 0.5, 0.38);
    mixInto(s, mechClick(rng, 0.06, 2400), 0.7, 0.55);         // bolt back
    mixInto(s, slide(rng, 0.08, 1500, 2500, 1.2), 0.2, 0.56);
    mixInto(s, mechClick(rng, 0.06, 1700), 0.9, 0.68);         // bolt home
    return finish(s, -6.0);
}

Sig dryFire(Rng& rng) {
    const double len = 0.15;
    Sig s(static_cast<std::size_t>(samplesFor(len)), 0.0);
    mixInto(s, mechClick(rng, 0.1, 2300), 1.0);
    mixInto(s, tone(0.1, 3700, 3700, 0, 0.0002, 0.005), 0.4);
    mixInto(s, mechClick(rng, 0.1, 1900), 0.4, 0.012);  // hammer
    return finish(s, -8.0);
}

Sig targetDown(Rng& rng) {
    const double len = 0.7;
    Sig s(static_cast<std::size_t>(samplesFor(len)), 0.0);
    mixInto(s, metalPartials(rng, len, 300 + rng.uniform01d() * 40, {1.0, 2.32, 4.25, 6.63}, {1, 0.6, 0.4, 0.25},
                             {0.30, 0.20, 0.12, 0.08}), 1.0);
    mixInto(s, noiseBurst(rng, 0.1, {Biquad::HighPass, 2500, 0.7071, 1}, 0.0001, 0.002), 0.5);
    mixInto(s, tone(0.3, 90, 60, 0.03, 0.001, 0.04), 0.8, 0.28);  // plate lands
    mixInto(s, noiseBurst(rng, 0.3, {Biquad::LowPass, 300, 0.7071, 2}, 0.001, 0.03), 0.6, 0.28);
    const double rattle[3][2] = {{0.32, 0.3}, {0.37, 0.2}, {0.40, 0.1}};
    for (const auto& r : rattle)
        mixInto(s, metalPartials(rng, 0.1, 600 + rng.uniform01d() * 100, {1.0, 2.32}, {1, 0.5}, {0.03, 0.02}), r[1], r[0]);
    return finish(s, -4.0);
}

Sig uiClick(Rng& rng) {
    const double len = 0.04;
    Sig s(static_cast<std::size_t>(samplesFor(len)), 0.0);
    mixInto(s, tone(len, 1800, 1800, 0, 0.0002, 0.005), 1.0);
    mixInto(s, noiseBurst(rng, len, {Biquad::HighPass, 4000, 0.7071, 1}, 0.0001, 0.001), 0.3);
    return finish(s, -10.0);
}

Sig hitMarker(Rng& rng) {
    const double len = 0.07;
    Sig s(static_cast<std::size_t>(samplesFor(len)), 0.0);
    mixInto(s, tone(len, 3000, 3000, 0, 0.0003, 0.012), 1.0);
    mixInto(s, tone(len, 4500, 4500, 0, 0.0003, 0.008), 0.5);
    mixInto(s, noiseBurst(rng, len, {Biquad::HighPass, 5000, 0.7071, 1}, 0.0001, 0.001), 0.3);
    return finish(s, -8.0);
}

struct Recipe {
    SfxInfo info;
    std::function<Sig(Rng&)> make;
};

const std::vector<Recipe>& recipes() {
    static const std::vector<Recipe> all = {
        {{"rifle_shot", "high-passed noise crack (6 ms) + 700 Hz band noise body + 110->45 Hz thump + low-passed noise tail (180 ms) + slap echo at 90 ms"}, rifleShot},
        {{"impact_concrete", "2.5 kHz band-passed noise snap + 160->90 Hz thud + gritty hiss + six random debris ticks"}, impactConcrete},
        {{"impact_metal", "struck-plate partials (~520 Hz x 1, 2.32, 4.25, 6.63, 9.38; 60-350 ms decays) + click"}, impactMetal},
        {{"impact_wood", "450 Hz band-passed noise knock + 190/420/780 Hz body resonances (15-40 ms) + click"}, impactWood},
        {{"grenade_bounce", "~1.8 kHz metal clink partials + 150 Hz thud + click, with a quieter second bounce ~0.13 s later"}, grenadeBounce},
        {{"grenade_throw", "whoosh: noise through a band-pass sweeping 350->1450->350 Hz under a sin^2 swell, plus cloth rustle"}, grenadeThrow},
        {{"smoke_hiss", "2.0 s seamless loop: 2.5-9 kHz hiss + 900 Hz band, slow loop-periodic wobble, 0.25 s equal-power seam crossfade", true}, smokeHiss},
        {{"footstep_1", "heel thump (low-passed noise + ~80 Hz) + toe 35-60 ms later + gravel grit; every parameter drawn per variation"}, footstep},
        {{"footstep_2", "footstep variation 2 (same recipe, own random parameters)"}, footstep},
        {{"footstep_3", "footstep variation 3 (same recipe, own random parameters)"}, footstep},
        {{"footstep_4", "footstep variation 4 (same recipe, own random parameters)"}, footstep},
        {{"reload", "magazine release click, slide out, magazine-in clack + thud, bolt back (click + slide), bolt home"}, reload},
        {{"dry_fire", "empty click: 2.3 kHz mechanical click + 3.7 kHz ping + hammer click 12 ms later"}, dryFire},
        {{"target_down", "low metal plate clank (~320 Hz partials) + plate landing thud at 0.28 s + three small rattles"}, targetDown},
        {{"ui_click", "40 ms: 1.8 kHz blip (5 ms decay) + tiny high click"}, uiClick},
        {{"hit_marker", "70 ms tick: 3 kHz + 4.5 kHz pings (8-12 ms decays) + high click"}, hitMarker},
    };
    return all;
}

}  // namespace

const std::vector<SfxInfo>& sfxCatalogue() {
    static const std::vector<SfxInfo> infos = [] {
        std::vector<SfxInfo> v;
        for (const auto& r : recipes()) v.push_back(r.info);
        return v;
    }();
    return infos;
}

std::vector<float> synthesizeSfx(const std::string& name, std::uint64_t seed) {
    for (const auto& r : recipes()) {
        if (r.info.name != name) continue;
        const std::uint64_t h = fnv1a(name);
        Rng rng(seed ^ h, h);
        const Sig s = r.make(rng);
        std::vector<float> out(s.size());
        for (std::size_t i = 0; i < s.size(); ++i) out[i] = static_cast<float>(std::clamp(s[i], -1.0, 1.0));
        return out;
    }
    throw std::invalid_argument("synthesizeSfx: unknown sound '" + name + "'");
}

std::vector<std::int16_t> toPcm16(const std::vector<float>& samples) {
    std::vector<std::int16_t> out(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double v = std::clamp(static_cast<double>(samples[i]), -1.0, 1.0) * 32767.0;
        out[i] = static_cast<std::int16_t>(std::lround(v));
    }
    return out;
}

WavData synthesizeSfxWav(const std::string& name, std::uint64_t seed) {
    WavData wav;
    wav.sampleRate = kSfxSampleRate;
    wav.channels = 1;
    wav.samples = toPcm16(synthesizeSfx(name, seed));
    return wav;
}

SfxLevels measureLevels(const std::vector<std::int16_t>& samples, int sampleRate) {
    SfxLevels l;
    if (samples.empty()) return l;
    double peak = 0, sum = 0;
    for (std::int16_t s : samples) {
        const double v = s / 32767.0;
        peak = std::max(peak, std::abs(v));
        sum += v * v;
    }
    const double rms = std::sqrt(sum / static_cast<double>(samples.size()));
    l.peakDbfs = peak > 0 ? 20.0 * std::log10(peak) : -999.0;
    l.rmsDbfs = rms > 0 ? 20.0 * std::log10(rms) : -999.0;
    l.seconds = static_cast<double>(samples.size()) / sampleRate;
    return l;
}

std::vector<SfxWritten> writeSfxSet(const std::string& directory, std::uint64_t seed) {
    std::filesystem::create_directories(directory);
    std::vector<SfxWritten> written;
    for (const auto& info : sfxCatalogue()) {
        const WavData wav = synthesizeSfxWav(info.name, seed);
        const std::string path = (std::filesystem::path(directory) / (info.name + ".wav")).string();
        writeWav(path, wav);
        written.push_back({info.name, path, measureLevels(wav.samples, wav.sampleRate)});
    }
    return written;
}

}  // namespace obscura::audio
