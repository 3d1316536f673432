// See game_decals.h.
#include "game_decals.h"

#include "core/rng.h"
#include "decals/decal_sign.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace obscura {

namespace {
constexpr double kPi = 3.14159265358979323846;
// debug-decals rays: 40 m reaches every wall of the arena from its spawn.
constexpr double kDebugRayLength = 40;
}  // namespace

std::vector<decals::BodyFrame> bodyFrames(const sim::Simulation& sim) {
    std::vector<decals::BodyFrame> out;
    for (const auto& b : sim.bodyPoses()) out.push_back({b.position, b.qx, b.qy, b.qz, b.qw});
    return out;
}

GameDecals::GameDecals(const Settings& settings, const map::Level& level, const std::vector<std::string>& searchDirs,
                       const sim::Simulation& sim)
    : set_(settings.decals) {
    std::vector<std::string> warnings;
    const decals::SignAtlas signs = decals::bakeSigns(decals::readSigns(level, searchDirs, warnings), OBSCURA_DECAL_FONT, warnings);
    for (const auto& w : warnings) std::cerr << "obscura: " << w << "\n";
    for (const auto& d : signs.decals) set_.addFixed(d);
    signTiles_ = signs.tiles;
    // debug-decals: rays from the start eye in a fixed spread of directions, a hole where each hits:
    // all round (75 degrees down to 5 up), or uniform over a cone about the start view.
    Rng rng(0xdeb6ULL);
    const Vec3 eye = sim.player().eye();
    const double coneCos = std::cos(settings.debugDecalsCone * kPi / 180);
    const double viewYaw = sim.player().yaw, viewPitch = sim.player().pitch;
    const Vec3 forward{-std::sin(viewYaw) * std::cos(viewPitch), std::sin(viewPitch), -std::cos(viewYaw) * std::cos(viewPitch)};
    const Vec3 right = normalize(cross(forward, Vec3{0, 1, 0})), up = cross(right, forward);
    for (int i = 0; i < settings.debugDecals; ++i) {
        Vec3 dir;
        if (settings.debugDecalsCone > 0) {
            const double c = 1 - rng.uniform01d() * (1 - coneCos), s = std::sqrt(std::max(0.0, 1 - c * c));
            const double phi = rng.uniform01d() * 2 * kPi;
            dir = forward * c + right * (s * std::cos(phi)) + up * (s * std::sin(phi));
        } else {
            const double yaw = rng.uniform01d() * 2 * kPi, pitch = (-75 + 80 * rng.uniform01d()) * kPi / 180;
            dir = {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
        }
        if (auto hit = sim.physics().rayCast(eye, eye + dir * kDebugRayLength))
            set_.add(decals::bulletHole(hit->point, hit->normal, set_.ring().added()));
    }
}

void GameDecals::onTick(const std::vector<sim::SimEvent>& events, const sim::Simulation& sim) {
    const std::vector<decals::BodyFrame> poses = bodyFrames(sim);
    for (const auto& e : events) {
        const auto n = set_.ring().added();
        if (e.type == sim::SimEventType::Impact && e.surface == sim::Surface::Level) {
            set_.add(decals::bulletHole(e.position, e.normal, n));
        } else if (e.type == sim::SimEventType::Impact && e.surface == sim::Surface::Prop) {
            // The body's pose now is the one the ray hit (the tick's physics step ran before combat).
            if (e.id >= 0 && e.id < static_cast<int>(poses.size()))
                set_.addOn(decals::bulletHole(e.position, e.normal, n), e.id, poses[static_cast<std::size_t>(e.id)]);
            else
                set_.add(decals::bulletHole(e.position, e.normal, n));
        } else if (e.type == sim::SimEventType::GrenadeDetonate) {
            set_.add(decals::scorch(e.position, n));
        }
    }
    set_.follow(poses);
}

}  // namespace obscura
