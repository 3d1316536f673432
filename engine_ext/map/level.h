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
#include "map/spawnflags.h"

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
    // map/surface_rules.h: drawn as the sky (Quake's sky* names, Quake 2's SURF_SKY): no shadow, no AO.
    bool sky = false;
    bool fence = false;  // a `{` texture: alpha-tested (holes where alpha < 0.5), still solid
    // Quake 2's `contents flags value` as the face wrote them (0 when it wrote none).
    std::uint32_t contents = 0, surfaceFlags = 0;
    int surfaceValue = 0;
};

// What a liquid brush holds (map/liquid.h classifies it; Quake's CONTENTS_* order of harm).
enum class LiquidKind : std::uint8_t { None, Water, Slime, Lava, Teleport };

struct LevelBrush {
    std::vector<LevelPolygon> faces;  // every plane of the brush, invisible ones included
    std::vector<Vec3> hullPoints;  // the brush's unique vertices (for convex-hull colliders, voxelising)
    Aabb bounds;
    bool solid = true;    // blocks the player, bullets and smoke
    bool visible = true;  // has at least one visible face
    LiquidKind liquid = LiquidKind::None;  // a liquid volume (non-solid, drawn two-sided)
    double liquidAlpha = 1;                // its opacity, 0..1 (map/liquid.h: the alpha keys)
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
    std::string file;  // where it was read when not the level's .map (an entity overlay), else ""
    bool isBrushEntity = false;
    // "file:line" of the entity for messages: its own file, or the level's.
    std::string where(const std::string& levelPath) const {
        return (file.empty() ? (levelPath.empty() ? std::string("<level>") : levelPath) : file) + ":" + std::to_string(pos.line);
    }

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

// Quake's light formulas, the `delay` key of a light entity (ericw-tools' numbering).
enum class LightFormula {
    Linear = 0,          // value - distance (in map units, scaled by `wait`), reaching 0 at `value` units
    Inverse = 1,         // value * 128 / distance
    InverseSquare = 2,   // value * 128^2 / distance^2
    None = 3,            // value at any distance
    LocalMinimum = 4,    // no falloff; raises the light to `value` rather than adding to it
    InverseSquareA = 5,  // value * 128^2 / (distance + 128)^2: no hot spot at the source
};

// A light entity (`light`, `light_fluoro`, `light_torch_*`, ...), compiled by map_lights.cpp; the
// falloff maths (the same as shaders/level/level.frag) is in quake_light.h.
struct LevelLight {
    Vec3 position;
    Vec3 colour{1, 1, 1};  // linear RGB, 0..1 (from `_color`/`color`, default white)
    double intensity = 300;  // Quake `light` value (300 default); negative lights subtract
    double radius = 0;       // metres the light reaches (linear: where it reaches 0; others: the gate, quake_light.h)
    LightFormula formula = LightFormula::Linear;
    double unitsPerMetreScaled = 32;  // map units a metre counts as in the falloff: units per metre x `wait` x worldspawn `_dist`
    double angleScale = 0.5;          // `_anglescale`: 0 = angle of incidence ignored, 1 = Lambert's cosine
    double falloffExponent = 1;       // Obscura's `_falloff_exponent` (linear lights): 1 = Quake, 2 = the smoother arena lamps
    bool spot = false;                // `target` or `mangle`: a spotlight
    Vec3 spotDirection{0, -1, 0};     // unit, the way the light travels
    double spotCosOuter = -1;         // cos of half the cone (`angle`/`_cone`, default 40 degrees)
    double spotCosInner = -1;         // cos of half the soft cone (`_softangle`), = spotCosOuter when none
    SourcePos pos;
};

// The level-wide lighting keys of worldspawn (and of a `_sun` light entity), read by map_lights.cpp
// and turned into the frame's constants by render/level_lighting.cpp.
struct LevelLightingKeys {
    bool hasLightEntities = false;  // the level places lights: its ambient defaults to Quake's (none)
    bool hasMinlight = false;       // worldspawn `light` / `_minlight`
    double minlight = 0;            // Quake light units
    Vec3 minlightColour{1, 1, 1};   // `_minlight_color` / `_mincolor`
    bool hasAmbient = false;        // Obscura's `_ambient_sky` / `_ambient_ground`: the hemisphere itself
    Vec3 ambientSky, ambientGround; // linear RGB irradiance from above / below
    double sunlight = 0;            // `_sunlight` (or a `_sun` light's `light`)
    Vec3 sunTravel{0, -1, 0};       // unit, world space, the way sunlight travels (`_sunlight_mangle`, ...)
    Vec3 sunColour{1, 1, 1};
    double dome = 0, domeBelow = 0; // `_sunlight2` (upper sky dome), `_sunlight3` (lower)
    Vec3 domeColour{1, 1, 1}, domeBelowColour{1, 1, 1};
};

// An `env_ambient` brush entity (map_lights.cpp): inside its brushes' box the level's ambient light
// is scaled by `scale` (an enclosed room keeps the sky's light out); the lighting pass applies it
// per pixel (render/ambient_area.h: ambientScaleAt).
struct AmbientArea {
    Aabb box;           // metres, world
    double scale = 0.1; // `ambient`
    double blend = 0;   // `blend`, metres: the fade across the faces, centred on them
    SourcePos pos;
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
    LevelLightingKeys lighting;
    std::vector<AmbientArea> ambientAreas;  // env_ambient, in file order
    std::vector<LevelModel> models;  // misc_model
    Vec3 playerStart;
    double playerStartYaw = 0;
    bool hasPlayerStart = false;
    Aabb bounds;                                 // of all brushes
    // Classes not in entity_classes.h, each listed once in file order, with how many entities had it.
    std::vector<std::string> unknownClassnames;
    std::vector<int> unknownClassCounts;  // parallel to unknownClassnames
    int skill = kDefaultSkill;  // the skill it was compiled for (spawnflags.h)
    int leftOutEntities = 0;    // entities (with their brushes) whose spawnflags exclude that skill
};

}  // namespace obscura::map
