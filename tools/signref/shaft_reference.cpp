// See shaft_reference.h.
#include "signref/shaft_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

namespace obscura::signref {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kTnear = 1e-4;  // metres: occlusion rays start and stop this far from their ends

// An orthonormal frame (t, b) around the unit vector n.
void frame(const Vec3& n, Vec3& t, Vec3& b) {
    const Vec3 a = std::fabs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    t = normalize(cross(a, n));
    b = cross(n, t);
}

// k-th of n stratified points in [0,1)^2: a ceil(sqrt(n)) grid, jittered.
void stratified(int k, int n, Rng& rng, double& u1, double& u2) {
    const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n)))));
    const int cx = k % side, cy = (k / side) % side;
    u1 = (cx + rng.uniform01d()) / side;
    u2 = (cy + rng.uniform01d()) / side;
}
}  // namespace

double phaseHG(double cosTheta, double g) {
    const double d = 1.0 + g * g - 2.0 * g * cosTheta;
    return 0.25 * (1.0 - g * g) / (d * std::sqrt(d));
}

Vec3 unshadowedIrradiance(const signs::SignSpec& sign, const Vec3& p) {
    // signIrradiance through a plate open everywhere: throughSign is then the cone alone, and the
    // cone and the window stay defined in one place (sign_light.cpp).
    static const signs::SignMask open = [] {
        signs::SignMask m;
        m.width = m.height = 1;
        m.texel = m.halfWidth = m.halfHeight = m.spread = 1e30;
        m.distance = {1e30f};
        return m;
    }();
    return signs::signIrradiance(sign, open, {}, p);
}

Vec3 lawIrradiance(const SignLight& sign, const RayScene* scene, const Vec3& p) {
    const Vec3 e = signs::signIrradiance(sign.spec, sign.mask, sign.holes, p);
    if (!scene || (e.x == 0 && e.y == 0 && e.z == 0)) return e;
    // one occlusion ray, towards the lamp's centre, as far as the plate's plane
    const Vec3 toLamp = sign.spec.lamp - p;
    const double b = dot(p - sign.spec.centre, sign.spec.facing), a = dot(sign.spec.centre - sign.spec.lamp, sign.spec.facing);
    const double dist = length(toLamp) * b / (a + b);
    return scene->occluded(p, normalize(toLamp), kTnear, dist - kTnear) ? Vec3{} : e;
}

double lampShare(const SignLight& sign, const RayScene* scene, const Vec3& p, int samples, Rng& rng) {
    const signs::SignSpec& s = sign.spec;
    const double b = dot(p - s.centre, s.facing);
    if (!(b > 0)) return 0;
    const Vec3 toLamp = s.lamp - p;
    const double D = length(toLamp);
    if (!(D > s.lightRadius)) return 0;  // inside the lamp (never in front of a plate it is behind)
    const Vec3 wc = toLamp / D;
    Vec3 t, bt;
    frame(wc, t, bt);
    const double cosMax = std::sqrt(std::max(0.0, 1 - (s.lightRadius / D) * (s.lightRadius / D)));
    samples = std::max(1, samples);
    int open = 0;
    for (int k = 0; k < samples; ++k) {
        double u1, u2;
        stratified(k, samples, rng, u1, u2);
        // uniform in the solid angle of the sphere: cos uniform in [cosMax, 1]
        const double c = 1 - u1 * (1 - cosMax), sn = std::sqrt(std::max(0.0, 1 - c * c)), phi = 2 * kPi * u2;
        const Vec3 w = wc * c + t * (sn * std::cos(phi)) + bt * (sn * std::sin(phi));
        const double toward = -dot(w, s.facing);
        if (!(toward > 0)) continue;  // never reaches the plate's plane
        const double dist = b / toward;  // to the plane
        const Vec3 q = p + w * dist - s.centre;
        const double x = dot(q, s.right), y = dot(q, s.up);
        if (!(std::fabs(x) < sign.mask.halfWidth && std::fabs(y) < sign.mask.halfHeight)) continue;
        if (!(signs::openDistance(sign.mask, sign.holes, x, y) > 0)) continue;
        if (scene && scene->occluded(p, w, kTnear, dist - kTnear)) continue;
        ++open;
    }
    return static_cast<double>(open) / samples;
}

ShaftReference::ShaftReference(const RayScene& scene, std::vector<SignLight> signs, const Medium& medium)
    : scene_(scene), signs_(std::move(signs)), medium_(medium) {}

double ShaftReference::lampShareCulled(const SignLight& sign, const Vec3& p, const ShaftOptions& opt, Rng& rng) const {
    if (opt.cull) {
        const signs::SignSpec& s = sign.spec;
        double x = 0, y = 0;
        if (!signs::planeCrossing(s, p, x, y)) return 0;
        // The lamp's footprint on the plane about (x, y), for a small sphere seen not too
        // obliquely: the sphere's angular radius times the distance to the plane, stretched by the
        // obliquity (along the ray and across it), with a quarter to spare.
        const Vec3 toLamp = s.lamp - p;
        const double D = length(toLamp);
        const double cosObl = -dot(toLamp / D, s.facing);
        const double sinA = s.lightRadius / D;
        if (cosObl > 0.2 && sinA < 0.2) {
            const double b = dot(p - s.centre, s.facing);
            const double tanA = sinA / std::sqrt(1 - sinA * sinA);
            const double footprint = 1.25 * (b / cosObl) * tanA / cosObl + 1e-9;
            const double plate = std::min(sign.mask.halfWidth - std::fabs(x), sign.mask.halfHeight - std::fabs(y));
            if (plate < -footprint) return 0;
            // The open region is where openDistance > 0. Bilinear between texels (and clamped to
            // the spread, with the holes' exact distances) it changes by at most sqrt(2) a metre:
            // below -1.5 x the footprint no sample can land on an open point.
            if (signs::openDistance(sign.mask, sign.holes, x, y) < -1.5 * footprint) return 0;
        }
    }
    return lampShare(sign, opt.geometry ? &scene_ : nullptr, p, opt.lampSamples, rng);
}

Vec3 ShaftReference::alongRay(const Vec3& eye, const Vec3& dir, double tmax, const ShaftOptions& opt, Rng& rng) const {
    if (!(opt.step > 0)) throw std::invalid_argument("signref: the step must be positive");
    const double u = rng.uniform01d();
    double T = 1;
    Vec3 L;
    for (long k = 0;; ++k) {
        const double t0 = k * opt.step;
        if (t0 >= tmax) break;
        const double t1 = std::min(t0 + opt.step, tmax), dt = t1 - t0;
        const Vec3 p = eye + dir * (t0 + u * dt);
        double sigmaT;
        Vec3 sigmaS;
        medium_.at(p, sigmaT, sigmaS);
        if (!(sigmaT > 0) && sigmaS.x == 0 && sigmaS.y == 0 && sigmaS.z == 0) continue;
        const double stepT = std::exp(-sigmaT * dt);
        Vec3 source;
        for (const SignLight& sign : signs_) {
            // Each point's lamp samples have their own stream, drawn whether or not they are
            // taken: culling changes no other point's samples (the tests compare cull on and off).
            const std::uint64_t hi = rng.nextU32(), lo = rng.nextU32();
            // The medium between p and the lamp, from the same stream's jitter (drawn always).
            const double shadowU = static_cast<double>(lo & 0xffffu) / 65536.0;
            const auto dimmed = [&](const Vec3& light) {
                if (!(opt.shadowStep > 0) || (light.x == 0 && light.y == 0 && light.z == 0)) return light;
                return light * std::exp(-medium_.opticalDepth(p, sign.spec.lamp, opt.shadowStep, shadowU));
            };
            if (opt.law) {
                source += dimmed(lawIrradiance(sign, opt.geometry ? &scene_ : nullptr, p) *
                                 phaseHG(dot(dir, normalize(p - sign.spec.lamp)), kShaftG));
                continue;
            }
            const Vec3 e0 = unshadowedIrradiance(sign.spec, p);
            if (e0.x == 0 && e0.y == 0 && e0.z == 0) continue;
            Rng lampRng((hi << 32) | lo);
            const double share = lampShareCulled(sign, p, opt, lampRng);
            if (share == 0) continue;
            source += dimmed(e0 * (share * phaseHG(dot(dir, normalize(p - sign.spec.lamp)), kShaftG)));
        }
        // (1 - e^(-sigma_t dt)) / sigma_t, which is dt in a medium that only scatters (the game's
        // thin haze: --haze-extinction 0).
        const double w = T * (sigmaT * dt > 1e-12 ? (1 - stepT) / sigmaT : dt);
        L += Vec3{sigmaS.x * source.x, sigmaS.y * source.y, sigmaS.z * source.z} * w;
        T *= stepT;
        if (T < 1e-9) break;
    }
    return L;
}

Vec3 ShaftReference::pixel(const CameraPose& pose, int width, int height, int x, int y, const ShaftOptions& opt) const {
    const std::uint64_t index = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(width) + static_cast<std::uint64_t>(x);
    Rng rng(opt.seed * 0x9e3779b97f4a7c15ULL + index, index);
    const int spp = std::max(1, opt.spp);
    Vec3 sum;
    for (int k = 0; k < spp; ++k) {
        double jx, jy;
        stratified(k, spp, rng, jx, jy);
        const Vec3 dir = cameraRay(pose, width, height, x + jx, y + jy);
        double tmax = opt.far;
        double t;
        Vec3 n;
        if (scene_.intersect(pose.eye, dir, 0, opt.far, t, n)) tmax = t;
        // The plates hide what lies behind them from the eye, as the game draws them (the lamp's
        // rays ignore them: the mask is their plate).
        for (const SignLight& sign : signs_) {
            const double dn = dot(dir, sign.spec.facing);
            if (std::fabs(dn) < 1e-12) continue;
            const double tp = dot(sign.spec.centre - pose.eye, sign.spec.facing) / dn;
            if (!(tp > 0 && tp < tmax)) continue;
            const Vec3 q = pose.eye + dir * tp - sign.spec.centre;
            if (std::fabs(dot(q, sign.spec.right)) <= sign.mask.halfWidth && std::fabs(dot(q, sign.spec.up)) <= sign.mask.halfHeight)
                tmax = tp;
        }
        sum += alongRay(pose.eye, dir, tmax, opt, rng);
    }
    return sum / spp;
}

FloatImage ShaftReference::render(const CameraPose& pose, int width, int height, const ShaftOptions& opt, int threads) const {
    if (width <= 0 || height <= 0) throw std::invalid_argument("signref: the image size must be positive");
    FloatImage img;
    img.width = width;
    img.height = height;
    img.rgb.assign(static_cast<std::size_t>(width) * height * 3, 0.0f);
    threads = std::max(1, threads);
    auto rows = [&](int y0) {
        for (int y = y0; y < height; y += threads)
            for (int x = 0; x < width; ++x) {
                const Vec3 L = pixel(pose, width, height, x, y, opt);
                float* o = &img.rgb[(static_cast<std::size_t>(y) * width + x) * 3];
                o[0] = static_cast<float>(L.x);
                o[1] = static_cast<float>(L.y);
                o[2] = static_cast<float>(L.z);
            }
    };
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(rows, t);
    for (auto& th : pool) th.join();
    return img;
}

bool width1090(const std::vector<double>& s, const std::vector<double>& v, double& width, double& s50) {
    if (s.size() != v.size() || s.size() < 3) return false;
    const auto [mn, mx] = std::minmax_element(v.begin(), v.end());
    const double lo = *mn, hi = *mx;
    if (!(hi - lo > 1e-12)) return false;
    auto level = [&](double f) { return lo + f * (hi - lo); };
    // the crossing of `lv` between i and i + 1
    auto at = [&](std::size_t i, double lv) {
        const double d = v[i + 1] - v[i];
        return d == 0 ? s[i] : s[i] + (s[i + 1] - s[i]) * (lv - v[i]) / d;
    };
    auto crosses = [&](std::size_t i, double lv) { return (v[i] - lv) * (v[i + 1] - lv) <= 0 && v[i] != v[i + 1]; };
    const double l50 = level(0.5), l10 = level(0.1), l90 = level(0.9);
    std::size_t i50 = s.size();
    for (std::size_t i = 0; i + 1 < s.size(); ++i)
        if (crosses(i, l50)) {
            i50 = i;
            break;
        }
    if (i50 == s.size()) return false;
    s50 = at(i50, l50);
    const bool rising = v[i50 + 1] > v[i50];
    // walk towards the dark side for 10 %, the bright side for 90 %
    auto search = [&](double lv, bool forward, double& out) {
        if (forward) {
            for (std::size_t i = i50; i + 1 < s.size(); ++i)
                if (crosses(i, lv)) return out = at(i, lv), true;
        } else {
            for (std::size_t i = i50 + 1; i-- > 0;)
                if (crosses(i, lv)) return out = at(i, lv), true;
        }
        return false;
    };
    double s10, s90;
    if (!search(l10, !rising, s10) || !search(l90, rising, s90)) return false;
    width = std::fabs(s90 - s10);
    return true;
}

double discEdge1090Share() {
    auto solve = [](double f) {  // discEdgeFraction(d, 1) = f, by bisection (it rises with d)
        double lo = -1, hi = 1;
        for (int i = 0; i < 200; ++i) {
            const double mid = (lo + hi) / 2;
            (signs::discEdgeFraction(mid, 1.0) < f ? lo : hi) = mid;
        }
        return (lo + hi) / 2;
    };
    return (solve(0.9) - solve(0.1)) / 2;
}

EdgeMeasure measureEdge(const SignLight& sign, const RayScene* scene, const Vec3& from, const Vec3& to, int points,
                        int lampSamples, std::uint64_t seed) {
    if (points < 3) throw std::invalid_argument("signref: an edge needs at least 3 points");
    EdgeMeasure m;
    const double len = length(to - from);
    for (int i = 0; i < points; ++i) {
        const double f = static_cast<double>(i) / (points - 1);
        Rng rng(seed * 0x9e3779b97f4a7c15ULL + static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(i));
        m.s.push_back(f * len);
        m.share.push_back(lampShare(sign, scene, from + (to - from) * f, lampSamples, rng));
    }
    double s50 = 0;
    m.found = width1090(m.s, m.share, m.width1090, s50);
    const Vec3 p50 = from + (to - from) * (len > 0 ? (m.found ? s50 : len / 2) / len : 0.0);
    m.b = dot(p50 - sign.spec.centre, sign.spec.facing);
    m.a = dot(sign.spec.centre - sign.spec.lamp, sign.spec.facing);
    m.penumbra = m.a > 0 ? 2 * sign.spec.lightRadius * m.b / m.a : 0;
    m.penumbra1090 = discEdge1090Share() * m.penumbra;
    m.cosAxis = dot(normalize(p50 - sign.spec.lamp), sign.spec.facing);
    m.sphere1090 = m.cosAxis > 0 ? m.penumbra1090 / m.cosAxis : 0;
    return m;
}

ShaftError compareShafts(const FloatImage& ref, const FloatImage& game) {
    if (ref.width != game.width || ref.height != game.height)
        throw std::runtime_error("the game's image is " + std::to_string(game.width) + "x" + std::to_string(game.height) +
                                 ", the reference " + std::to_string(ref.width) + "x" + std::to_string(ref.height));
    ShaftError e;
    double se = 0, so = 0, sum = 0;
    for (std::size_t i = 0; i < ref.rgb.size(); ++i) {
        const double r = ref.rgb[i], g = game.rgb[i];
        if (!std::isfinite(g)) throw std::runtime_error("the game's image has a non-finite value at pixel " + std::to_string(i / 3));
        se += (g - r) * (g - r);
        so += r * r;
        sum += r;
        e.maxRef = std::max(e.maxRef, r);
    }
    const double n = static_cast<double>(std::max<std::size_t>(1, ref.rgb.size()));
    e.rmse = std::sqrt(se / n);
    e.rmseOff = std::sqrt(so / n);
    e.meanRef = sum / n;
    e.pixels = ref.rgb.size() / 3;
    return e;
}

}  // namespace obscura::signref
