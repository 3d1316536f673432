// See smoke_lamps.h.
#include "smoke/smoke_lamps.h"

#include "map/quake_light.h"
#include "smoke/smoke_shared.h"

#include <algorithm>
#include <tuple>
#include <utility>

namespace obscura::smoke {

namespace {
// A light that reaches nothing still needs a positive range (the march divides by it).
constexpr double kMinLampRange = 1e-3;

double distanceToBox(const Vec3& p, const SmokeBox& b) {
    const Vec3 hi = b.min + b.size;
    const Vec3 nearest{std::clamp(p.x, b.min.x, hi.x), std::clamp(p.y, b.min.y, hi.y), std::clamp(p.z, b.min.z, hi.z)};
    return length(p - nearest);
}
}  // namespace

std::vector<SmokeLamp> levelLamps(const map::Level& level) {
    const double size = level.bounds.empty() ? 1.0 : length(level.bounds.max - level.bounds.min);
    std::vector<SmokeLamp> lamps;
    for (const auto& l : level.lights) {
        if (l.spot) continue;
        const double k = l.intensity / map::kQuakeLightUnit;
        lamps.push_back({l.position, l.colour * k, std::max(map::lightReach(l, size), kMinLampRange)});
    }
    std::sort(lamps.begin(), lamps.end(), [](const SmokeLamp& a, const SmokeLamp& b) {
        return std::tie(a.position.x, a.position.y, a.position.z) < std::tie(b.position.x, b.position.y, b.position.z);
    });
    return lamps;
}

LampChoice chooseLamps(const std::vector<SmokeBox>& boxes, const std::vector<SmokeLamp>& level,
                       const std::vector<SmokeLamp>& signs) {
    LampChoice choice;
    std::vector<std::pair<double, std::size_t>> scored;  // (-brightness at the nearest box, lamp)
    for (std::size_t l = 0; l < level.size(); ++l) {
        const SmokeLamp& p = level[l];
        double best = 0;
        for (const SmokeBox& b : boxes) {
            const double d = distanceToBox(p.position, b);
            if (d >= p.range) continue;
            const double f = 1 - d / p.range;
            best = std::max(best, (0.2126 * p.colour.x + 0.7152 * p.colour.y + 0.0722 * p.colour.z) * f * f);
        }
        if (best > 0) scored.push_back({-best, l});
    }
    std::sort(scored.begin(), scored.end());
    for (std::size_t i = 0; i < scored.size() && i < SMOKE_MAX_LIGHTS; ++i) choice.bound.push_back(level[scored[i].second]);

    std::vector<std::pair<double, std::size_t>> near;  // (distance to the nearest box, sign lamp)
    for (std::size_t s = 0; s < signs.size(); ++s) {
        double nearest = signs[s].range;
        for (const SmokeBox& b : boxes) nearest = std::min(nearest, distanceToBox(signs[s].position, b));
        if (nearest < signs[s].range) near.push_back({nearest, s});
    }
    std::sort(near.begin(), near.end());
    near.resize(std::min(near.size(), kShadowedSignLamps));
    choice.shadowedLevelLamps = std::min(choice.bound.size(), kShadowedLamps - near.size());
    for (std::size_t l = 0; l < choice.shadowedLevelLamps; ++l) choice.shadowed.push_back(choice.bound[l].position);
    for (const auto& [d, s] : near) choice.shadowed.push_back(signs[s].position);
    return choice;
}

}  // namespace obscura::smoke
