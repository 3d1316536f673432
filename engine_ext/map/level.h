// A compiled level: what a Quake / Valve-220 `.map` becomes once its brushes are turned into
// polygons and its entities into game objects. Plain C++ (no OGRE, no Bullet): rendering,
// physics, smoke voxelisation and the ray-traced AO reference all read this one structure.
//
// Coordinates: OGRE convention, Y up, right-handed, metres. A Quake point (x, y, z) in map
// units becomes (x, z, -y) / unitsPerMetre. Yaw angles are radians about +Y, 0 = facing -Z
// (OGRE's camera default); a Quake `angle` a (degrees, CCW from +X seen from above) becomes
// yaw = radians(a) - pi/2.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/vec3.h"

namespace obscura::map {

struct SourcePos {
    int line = 0;    // 1-based
    int column = 0;  // 1-based
};

struct Aabb {
    Vec3 min{1e300, 1e300, 1e300};
    Vec3 max{-1e300, -1e300, -1e300};
    void extend(const Vec3& p) {
        min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
        max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
    }
    bool empty() const { return min.x > max.x; }
};

struct LevelVertex {
    Vec3 position;  // metres, world space
    Vec3 normal;    // unit, the face's outward normal
    double u = 0, v = 0;  // texture coordinates in texture repeats (1.0 = one texture width)
};

struct LevelPolygon {
    std::vector<LevelVertex> vertices;  // convex, counter-clockwise seen from the front (outside)
    Vec3 normal;                        // outward
    std::string texture;                // the face's texture name as written in the map
    bool visible = true;                // false for skip / hint / caulk / nodraw / clip / trigger faces
};

struct LevelBrush {
    std::vector<LevelPolygon> faces;
    std::vector<Vec3> hullPoints;  // the brush's unique vertices (for convex-hull colliders, voxelising)
    Aabb bounds;
    bool solid = true;    // blocks the player, bullets and smoke
    bool visible = true;  // has at least one visible face
    int entityIndex = 0;  // index into Level::entities (0 = worldspawn)
    // Belongs to a moving brush entity (func_door, func_door_secret, func_plat, func_button,
    // func_train: isMoverClass): solid, but not part of the static world. Physics, rendering and
    // the smoke's voxels leave it out of the world and treat its entity's brushes as one mover.
    bool mover = false;
    SourcePos pos;        // where the brush opens in the .map
};

struct LevelEntity {
    std::string classname;
    std::vector<std::pair<std::string, std::string>> keys;  // in file order
    bool hasOrigin = false;
    Vec3 origin;      // converted to metres / Y-up
    double yaw = 0;   // radians, see the header comment
    SourcePos pos;
    bool isBrushEntity = false;

    // Value of a key, or `fallback` if absent.
    const std::string& value(const std::string& key, const std::string& fallback = empty()) const {
        for (const auto& kv : keys)
            if (kv.first == key) return kv.second;
        return fallback;
    }
    bool has(const std::string& key) const {
        for (const auto& kv : keys)
            if (kv.first == key) return true;
        return false;
    }
    static const std::string& empty() {
        static const std::string e;
        return e;
    }
};

struct LevelLight {
    Vec3 position;
    Vec3 colour{1, 1, 1};  // linear RGB, 0..1 (from `_color`/`color`, default white)
    double intensity = 300;  // Quake `light` value (300 default)
    double radius = 0;       // metres of influence: `light` value / unitsPerMetre... see map_compile.cpp
};

struct LevelModel {
    std::string mesh;  // OGRE .mesh name or path from the `model` key
    Vec3 origin;
    double yaw = 0;
    double scale = 1;
    int entityIndex = 0;
    SourcePos pos;  // the misc_model entity in the .map
};

struct Level {
    std::string sourcePath;
    double unitsPerMetre = 32;
    std::vector<LevelEntity> entities;  // all entities in file order (0 = worldspawn)
    std::vector<LevelBrush> brushes;
    std::vector<LevelLight> lights;
    std::vector<LevelModel> models;  // misc_model
    Vec3 playerStart;
    double playerStartYaw = 0;
    bool hasPlayerStart = false;
    Aabb bounds;                                 // of all brushes
    std::vector<std::string> unknownClassnames;  // each listed once
};

}  // namespace obscura::map
