// Hand-built levels for the simulation tests: boxes and wedges as solid brushes (hull points and
// bounds only; physics needs no faces), plus small helpers to drive a Simulation.
#pragma once

#include "map/level.h"
#include "sim/simulation.h"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace obscura::sim::testlevels {

constexpr double kPi = 3.14159265358979323846;
// The player's capsule radius (PlayerTuning's default), for "stops at the wall" checks.
constexpr double kRadius = 0.35;

inline map::LevelBrush box(Vec3 min, Vec3 max) {
    map::LevelBrush b;
    for (int i = 0; i < 8; ++i)
        b.hullPoints.push_back({i & 1 ? max.x : min.x, i & 2 ? max.y : min.y, i & 4 ? max.z : min.z});
    b.bounds.extend(min);
    b.bounds.extend(max);
    b.solid = true;
    return b;
}

// A ramp rising towards -Z: from z = z0 (height 0) to z = z0 - run (height rise), x in [x0, x1].
inline map::LevelBrush ramp(double x0, double x1, double z0, double run, double rise) {
    map::LevelBrush b;
    b.hullPoints = {{x0, 0, z0}, {x1, 0, z0}, {x0, 0, z0 - run}, {x1, 0, z0 - run},
                    {x0, rise, z0 - run}, {x1, rise, z0 - run}};
    b.bounds.extend({x0, 0, z0 - run});
    b.bounds.extend({x1, rise, z0});
    return b;
}

// A liquid box with its six faces (the liquid query reads their planes; physics ignores it).
inline map::LevelBrush liquidBox(Vec3 min, Vec3 max, map::LiquidKind kind = map::LiquidKind::Water) {
    map::LevelBrush b = box(min, max);
    b.solid = false;
    b.liquid = kind;
    const Vec3 normals[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    for (int i = 0; i < 6; ++i) {
        map::LevelPolygon f;
        f.normal = normals[i];
        f.texture = "*water1";
        map::LevelVertex v;
        v.position = i % 2 == 0 ? min : max;  // a point on the face's plane
        v.normal = f.normal;
        f.vertices.push_back(v);
        b.faces.push_back(f);
    }
    return b;
}

// A 40 x 40 m floor slab whose top is at y = 0, the player at the origin facing -Z.
inline map::Level floorLevel() {
    map::Level l;
    l.sourcePath = "test.map";
    l.entities.push_back({});
    l.entities[0].classname = "worldspawn";
    l.brushes.push_back(box({-20, -1, -20}, {20, 0, 20}));
    l.hasPlayerStart = true;
    l.playerStart = {0, 0, 0};
    return l;
}

inline map::LevelEntity crate(const Vec3& origin) {
    map::LevelEntity e;
    e.classname = "prop_crate";
    e.hasOrigin = true;
    e.origin = origin;
    return e;
}

// An entity with keys; its brushes (boxes) tagged with its index and as a mover when it is one.
inline int addEntity(map::Level& l, const std::string& classname, std::vector<std::pair<std::string, std::string>> keys,
              std::vector<std::pair<Vec3, Vec3>> boxes = {}, int line = 0) {
    map::LevelEntity e;
    e.classname = classname;
    e.keys = std::move(keys);
    e.keys.insert(e.keys.begin(), {"classname", classname});
    e.pos.line = line;
    e.isBrushEntity = !boxes.empty();
    const int index = static_cast<int>(l.entities.size());
    for (const auto& [mn, mx] : boxes) {
        map::LevelBrush b = box(mn, mx);
        b.entityIndex = index;
        b.mover = classname.rfind("func_", 0) == 0;
        b.solid = classname.rfind("trigger_", 0) != 0;
        l.brushes.push_back(b);
    }
    l.entities.push_back(e);
    return index;
}

inline int addPoint(map::Level& l, const std::string& classname, const Vec3& origin, double yaw,
             std::vector<std::pair<std::string, std::string>> keys) {
    const int i = addEntity(l, classname, std::move(keys));
    l.entities[static_cast<std::size_t>(i)].hasOrigin = true;
    l.entities[static_cast<std::size_t>(i)].origin = origin;
    l.entities[static_cast<std::size_t>(i)].yaw = yaw;
    return i;
}

inline PlayerCommand walk(float forward = 1, float right = 0) {
    PlayerCommand c;
    c.forward = forward;
    c.right = right;
    return c;
}

// A start at `feet` facing `yaw` instead of the level's info_player_start.
inline SimConfig startAt(const Vec3& feet, double yaw = 0) {
    SimConfig c;
    c.overrideStart = true;
    c.startFeet = feet;
    c.startYaw = yaw;
    return c;
}

inline void run(Simulation& s, const PlayerCommand& c, int ticks) {
    for (int i = 0; i < ticks; ++i) s.step(c);
}

}  // namespace obscura::sim::testlevels
