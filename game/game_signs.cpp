// See game_signs.h.
#include "game_signs.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>

namespace obscura {

GameSigns::GameSigns(const map::Level& level, const std::vector<std::string>& fontDirs) {
    std::vector<std::string> warnings;
    for (signs::SignSpec& spec : signs::readSignLights(level, fontDirs, warnings)) {
        try {
            // Exact out to the widest penumbra, and at least 4 texels (the plate's own edge filter
            // reads the field across a pixel's footprint).
            signs::SignMask mask = signs::bakeMask(spec, signs::maxPenumbraRadius(spec));
            if (mask.spread < 4 * mask.texel) mask = signs::bakeMask(spec, 4 * mask.texel);
            masks_.push_back(std::move(mask));
            specs_.push_back(std::move(spec));
        } catch (const std::runtime_error& e) {
            warnings.push_back(spec.where + ": light_sign skipped: " + e.what());
        }
    }
    for (const auto& w : warnings) std::cerr << "obscura: " << w << "\n";
    holes_.resize(specs_.size());
}

bool rayCrossesPlate(const signs::SignSpec& sign, const signs::SignMask& mask, const Vec3& origin, const Vec3& dir,
                     double maxT, double& t, double& x, double& y) {
    const double dn = dot(dir, sign.facing);
    if (std::fabs(dn) < 1e-9) return false;
    t = dot(sign.centre - origin, sign.facing) / dn;
    if (!(t > 0 && t < maxT)) return false;
    const Vec3 q = origin + dir * t - sign.centre;
    x = dot(q, sign.right);
    y = dot(q, sign.up);
    return std::fabs(x) <= mask.halfWidth && std::fabs(y) <= mask.halfHeight;
}

void GameSigns::onTick(const std::vector<sim::SimEvent>& events) {
    for (std::size_t e = 0; e < events.size(); ++e) {
        if (events[e].type != sim::SimEventType::Shot) continue;
        // The shot's own impact follows it in the list (combat.cpp): the plate must come first.
        double maxT = std::numeric_limits<double>::infinity();
        for (std::size_t f = e + 1; f < events.size() && events[f].type != sim::SimEventType::Shot; ++f)
            if (events[f].type == sim::SimEventType::Impact) {
                maxT = length(events[f].position - events[e].position);
                break;
            }
        for (std::size_t s = 0; s < specs_.size(); ++s) {
            double t = 0, x = 0, y = 0;
            if (!rayCrossesPlate(specs_[s], masks_[s], events[e].position, events[e].direction, maxT, t, x, y)) continue;
            holes_[s].add({x, y, kSignHoleRadius});
            ++version_;
        }
    }
}

}  // namespace obscura
