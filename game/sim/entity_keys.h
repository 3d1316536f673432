// Reading Quake entity keys for the movers and triggers (sim/movers.h, sim/triggers.h): numbers
// the way QuakeC's atof reads them, Quake directions (`angle`, `angles`, -1 up, -2 down) turned
// into this project's Y-up world, and units turned into metres. Bad values never stop a level:
// each is a `file:line` warning and the key's default is used (a level must still load).
#pragma once

#include "core/vec3.h"
#include "map/level.h"

#include <string>
#include <vector>

namespace obscura::sim {

class EntityKeys {
public:
    EntityKeys(const map::Level& level, std::vector<std::string>& warnings) : level_(level), warnings_(warnings) {}

    const map::Level& level() const { return level_; }
    double unitsPerMetre() const { return level_.unitsPerMetre; }

    // "file:line: <classname>: <text>" into the warnings.
    void warn(const map::LevelEntity& e, const std::string& text) const;

    // The key as a number; `fallback` when absent, or (warned) when it does not start with one.
    // QuakeC's atof: "-30 0 0" reads as -30.
    double number(const map::LevelEntity& e, const char* key, double fallback) const;
    // Quake's "0 or absent means the default": a positive number, else `fallback` (a negative
    // one is warned). For speeds, lips, heights.
    double positive(const map::LevelEntity& e, const char* key, double fallback) const;
    int spawnflags(const map::LevelEntity& e) const { return static_cast<int>(number(e, "spawnflags", 0)); }

    // Quake's SetMovedir: `angle` -1 is up, -2 down, else the yaw (degrees CCW from +X seen from
    // above); `angles` "pitch yaw roll" when present (pitch positive looks down). Unit, world space.
    Vec3 moveDirection(const map::LevelEntity& e) const;
    // QuakeC's makevectors(angles) of the entity's yaw alone: forward and right, world space.
    void yawVectors(const map::LevelEntity& e, Vec3& forward, Vec3& right) const;
    bool hasDirection(const map::LevelEntity& e) const { return e.has("angle") || e.has("angles"); }

    // A Quake vector (x, y, z) in world space (x, z, -y); no scaling.
    static Vec3 fromQuake(double x, double y, double z) { return {x, z, -y}; }
    // A world-space direction or extent as Quake's (x, y, z) components.
    static Vec3 toQuake(const Vec3& w) { return {w.x, -w.z, w.y}; }

private:
    bool leadingNumber(const std::string& s, double& out) const;

    const map::Level& level_;
    std::vector<std::string>& warnings_;
};

}  // namespace obscura::sim
