// See map_lights.h.
#include "map/map_lights.h"

#include "map/entity_classes.h"
#include "map/input_file.h"
#include "map/map_compile.h"
#include "map/quake_light.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>

namespace obscura::map {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Quake (x, y, z) -> Y-up (x, z, -y), as map_compile.cpp.
Vec3 toWorld(const Vec3& q) { return {q.x, q.z, -q.y}; }

std::string shortNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.15g", v);
    return buf;
}

// The keys of one entity, read with warnings that name the file and the entity's line.
class Keys {
public:
    Keys(const LevelEntity& e, const std::string& path, std::vector<std::string>* warnings)
        : e_(e), path_(path), warnings_(warnings) {}

    void warn(const std::string& w) const {
        if (warnings_) warnings_->push_back(path_ + ":" + std::to_string(e_.pos.line) + ": " + w);
    }
    const std::string* find(std::initializer_list<const char*> names) const {
        for (const char* n : names)
            if (e_.has(n)) return &e_.value(n);
        return nullptr;
    }
    // Up to `n` leading numbers of the first present key (like Quake's atof, trailing text ignored);
    // how many were read, 0 with a warning when the value does not start with a number.
    int numbers(const char* key, double* out, int n) const {
        const std::string& s = e_.value(key);
        const char* p = s.data();
        const char* const end = p + s.size();
        int got = 0;
        for (; got < n; ++got) {
            while (p < end && (*p == ' ' || *p == '\t')) ++p;
            if (p < end && *p == '+') ++p;
            double v = 0;
            const auto r = std::from_chars(p, end, v);
            if (r.ec != std::errc() || !std::isfinite(v)) break;
            out[got] = v;
            p = r.ptr;
        }
        return got;
    }
    // A number key among `names` within [lo, hi], else `fallback` (a warning when present but bad).
    double number(std::initializer_list<const char*> names, double fallback, double lo, double hi) const {
        for (const char* key : names) {
            if (!e_.has(key)) continue;
            double v = 0;
            if (numbers(key, &v, 1) != 1) {
                warn("'" + std::string(key) + "' value '" + errorText(e_.value(key)) + "' is not a number; using " + shortNumber(fallback));
                return fallback;
            }
            if (v < lo || v > hi) {
                warn("'" + std::string(key) + "' value '" + errorText(e_.value(key)) + "' is out of range, expected " + shortNumber(lo) +
                     " to " + shortNumber(hi) + "; using " + shortNumber(fallback));
                return fallback;
            }
            return v;
        }
        return fallback;
    }
    // An RGB colour key: "r g b" as 0..1 or 0..255 (any component above 1: divided by 255).
    bool colour(std::initializer_list<const char*> names, Vec3& out) const {
        for (const char* key : names) {
            if (!e_.has(key)) continue;
            double c[3];
            if (numbers(key, c, 3) != 3 || c[0] < 0 || c[1] < 0 || c[2] < 0) {
                warn("'" + std::string(key) + "' value '" + errorText(e_.value(key)) + "' is not three numbers from 0 to 255; ignored");
                return false;
            }
            out = {c[0], c[1], c[2]};
            if (c[0] > 1 || c[1] > 1 || c[2] > 1) out = out / 255.0;
            return true;
        }
        return false;
    }
    // "yaw pitch [roll]" in degrees (Quake: yaw about +Z from +X, pitch up) -> the world direction.
    bool mangle(std::initializer_list<const char*> names, Vec3& out) const {
        for (const char* key : names) {
            if (!e_.has(key)) continue;
            double a[3];
            if (numbers(key, a, 3) < 2) {
                warn("'" + std::string(key) + "' value '" + errorText(e_.value(key)) + "' is not 'yaw pitch roll'; ignored");
                return false;
            }
            const double yaw = a[0] * kPi / 180, pitch = a[1] * kPi / 180;
            out = normalize(toWorld({std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)}));
            return true;
        }
        return false;
    }

private:
    const LevelEntity& e_;
    const std::string& path_;
    std::vector<std::string>* warnings_;
};

void readWorldspawn(const LevelEntity& world, const Keys& k, LevelLightingKeys& out) {
    if (k.find({"_minlight", "light"})) {
        out.hasMinlight = true;
        out.minlight = k.number({"_minlight", "light"}, 0, 0, kMaxLightValue);
    }
    k.colour({"_minlight_color", "_mincolor"}, out.minlightColour);
    const bool sky = world.has("_ambient_sky"), ground = world.has("_ambient_ground");
    if (sky || ground) {
        // Obscura's own keys, linear irradiance (not 0..255): read as given, up to 16 (HDR).
        out.hasAmbient = true;
        for (auto [key, dest] : {std::pair{"_ambient_sky", &out.ambientSky}, std::pair{"_ambient_ground", &out.ambientGround}}) {
            if (!world.has(key)) continue;
            double c[3];
            if (k.numbers(key, c, 3) == 3 && c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] <= 16 && c[1] <= 16 && c[2] <= 16)
                *dest = {c[0], c[1], c[2]};
            else
                k.warn("'" + std::string(key) + "' value '" + errorText(world.value(key)) + "' is not three numbers from 0 to 16; using 0 0 0");
        }
    }
    out.sunlight = k.number({"_sunlight"}, 0, -kMaxLightValue, kMaxLightValue);
    // ericw-tools reads _sunlight_mangle and _sun_mangle; _sun_angle is an older editors' spelling.
    k.mangle({"_sunlight_mangle", "_sun_mangle", "_sun_angle"}, out.sunTravel);
    k.colour({"_sunlight_color"}, out.sunColour);
    out.dome = k.number({"_sunlight2"}, 0, 0, kMaxLightValue);
    k.colour({"_sunlight2_color", "_sunlight_color2"}, out.domeColour);
    out.domeBelow = k.number({"_sunlight3"}, 0, 0, kMaxLightValue);
    k.colour({"_sunlight3_color", "_sunlight_color3"}, out.domeBelowColour);
}
}  // namespace

double ambientScaleAt(const std::vector<AmbientArea>& areas, const Vec3& p) {
    double factor = 1;
    for (const AmbientArea& a : areas) {
        // The signed distance inside the box along the nearest face (negative outside it).
        const double inside = std::min({p.x - a.box.min.x, a.box.max.x - p.x, p.y - a.box.min.y, a.box.max.y - p.y,
                                        p.z - a.box.min.z, a.box.max.z - p.z}) + kAmbientAreaGrace;
        const double w = a.blend > 0 ? std::clamp(0.5 + inside / a.blend, 0.0, 1.0) : (inside >= 0 ? 1.0 : 0.0);
        factor = std::min(factor, 1 + (a.scale - 1) * w);
    }
    return factor;
}

namespace {
void readAmbientAreas(Level& level, const std::string& path, std::vector<std::string>* warnings) {
    for (std::size_t ei = 0; ei < level.entities.size(); ++ei) {
        const LevelEntity& e = level.entities[ei];
        if (e.classname != "env_ambient") continue;
        const Keys k(e, path, warnings);
        AmbientArea a;
        a.pos = e.pos;
        for (const LevelBrush& b : level.brushes)
            if (b.entityIndex == static_cast<int>(ei)) a.box.extend(b.bounds.min), a.box.extend(b.bounds.max);
        if (a.box.empty()) {
            k.warn("env_ambient has no brushes; skipped");
            continue;
        }
        a.scale = k.number({"ambient"}, 0.1, 0, 1);
        a.blend = k.number({"blend"}, 0, 0, 4);
        level.ambientAreas.push_back(a);
    }
}
}  // namespace

void compileLights(Level& level, const std::string& path, std::vector<std::string>* warnings) {
    if (level.entities.empty()) return;
    readAmbientAreas(level, path, warnings);
    const LevelEntity& world = level.entities.front();
    const Keys worldKeys(world, path, warnings);
    readWorldspawn(world, worldKeys, level.lighting);
    // Worldspawn `_dist` scales every light's fade distance (ericw-tools).
    const double dist = worldKeys.number({"_dist"}, 1, 1e-3, 1e3);
    const double levelSize = level.bounds.empty() ? 1.0 : length(level.bounds.max - level.bounds.min);

    std::map<std::string, const LevelEntity*> named;
    for (const LevelEntity& e : level.entities)
        if (e.hasOrigin && e.has("targetname")) named.emplace(e.value("targetname"), &e);

    bool sunFromEntity = false;
    for (const LevelEntity& e : level.entities) {
        const EntityClass* known = findEntityClass(e.classname);  // the table's light classes only
        if (!known || known->role != EntityRole::Light || !e.hasOrigin) continue;
        const Keys k(e, path, warnings);
        const char* valueKey = e.has("light") ? "light" : "_light";
        if (e.has(valueKey)) {
            double v = 0;
            if (k.numbers(valueKey, &v, 1) == 1 && std::fabs(v) > kMaxLightValue)
                throw MapError(path + ":" + std::to_string(e.pos.line) + ": light '" + valueKey + "' value '" + errorText(e.value(valueKey)) +
                               "' is out of range, expected -" + shortNumber(kMaxLightValue) + " to " + shortNumber(kMaxLightValue));
        }
        LevelLight l;
        l.pos = e.pos;
        l.position = e.origin;
        l.intensity = k.number({valueKey}, 300, -kMaxLightValue, kMaxLightValue);
        k.colour({"_color", "color"}, l.colour);

        // The spot direction: towards `target`'s origin, else `mangle`.
        bool aimed = false;
        if (e.has("target")) {
            const auto it = named.find(e.value("target"));
            if (it == named.end())
                k.warn("'target' value '" + errorText(e.value("target")) + "' names no entity with an origin; not a spotlight");
            else if (length(it->second->origin - e.origin) < 1e-9)
                k.warn("'target' '" + errorText(e.value("target")) + "' is at the light's own origin; not a spotlight");
            else {
                l.spotDirection = normalize(it->second->origin - e.origin);
                aimed = true;
            }
        }
        if (!aimed) aimed = k.mangle({"mangle"}, l.spotDirection);

        if (std::atof(e.value("_sun", "0").c_str()) == 1) {
            // ericw-tools: a `_sun` light is the sun (when worldspawn sets none); the entity casts nothing.
            if (level.lighting.sunlight == 0 && !sunFromEntity) {
                sunFromEntity = true;
                level.lighting.sunlight = l.intensity;
                level.lighting.sunColour = l.colour;
                if (aimed) level.lighting.sunTravel = l.spotDirection;
            }
            continue;
        }
        if (std::atof(e.value("_nostaticlight", "0").c_str()) == 1) continue;
        // Quake's START_OFF (spawnflags 1) on a named light: dark until triggered (not yet switchable here).
        if (e.has("targetname") && (std::atoi(e.value("spawnflags", "0").c_str()) & 1)) continue;

        const double delay = k.number({"delay"}, 0, 0, 5);
        if (delay != std::floor(delay))
            k.warn("'delay' value '" + errorText(e.value("delay")) + "' is not a whole number from 0 to 5; using " + shortNumber(std::floor(delay)));
        l.formula = static_cast<LightFormula>(static_cast<int>(delay));
        const double wait = k.number({"wait"}, 1, 1e-3, 1e3);
        l.unitsPerMetreScaled = level.unitsPerMetre * wait * dist;
        l.angleScale = k.number({"_anglescale", "_anglesense"}, 0.5, 0, 1);
        l.falloffExponent = k.number({"_falloff_exponent"}, 1, 0.25, 8);
        const double falloff = k.number({"_falloff"}, 0, 0, kMaxLightValue);
        if (falloff > 0 && l.formula != LightFormula::Linear) k.warn("'_falloff' only applies to delay 0 lights; ignored");
        l.radius = l.formula == LightFormula::Linear
                       ? (falloff > 0 ? falloff / level.unitsPerMetre : std::fabs(l.intensity) / l.unitsPerMetreScaled)
                       : lightReach(l, levelSize);

        if (aimed) {
            l.spot = true;
            // `_cone` (other editors) or ericw-tools' `angle`: the full cone, degrees; 0 = the default.
            double cone = k.number({"_cone", "angle"}, kDefaultSpotCone, 0, 180);
            if (cone <= 0) cone = kDefaultSpotCone;
            double soft = k.number({"_softangle"}, 0, 0, 180);
            if (soft >= cone) {
                k.warn("'_softangle' " + shortNumber(soft) + " is not smaller than the cone " + shortNumber(cone) + "; a hard edge");
                soft = 0;
            }
            l.spotCosOuter = std::cos(cone * 0.5 * kPi / 180);
            l.spotCosInner = soft > 0 ? std::cos(soft * 0.5 * kPi / 180) : l.spotCosOuter;
        }
        level.lights.push_back(l);
        level.lighting.hasLightEntities = true;
    }
}

}  // namespace obscura::map
