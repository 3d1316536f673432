// See map_compile.h.
#include "map/map_compile.h"

#include "map/brush_geometry.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>

namespace obscura::map {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Quake's default units per metre: the player is 56 units tall, about 1.75 m.
constexpr double kDefaultUnitsPerMetre = 32.0;
// info_player_start's origin is the player's centre, 24 units above the feet (Quake's hull).
constexpr double kPlayerOriginAboveFeet = 24.0;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}
bool startsWith(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

// Quake (x, y, z) -> Y-up (x, z, -y): a rotation, so windings and normals stay consistent.
Vec3 toWorld(const Vec3& q) { return {q.x, q.z, -q.y}; }

bool parseVec(const std::string& s, Vec3& out) {
    std::istringstream is(s);
    return static_cast<bool>(is >> out.x >> out.y >> out.z);
}

enum class BrushClass { Solid, NonSolid, Trigger };

BrushClass classify(const std::string& classname) {
    if (startsWith(classname, "trigger_")) return BrushClass::Trigger;
    if (classname == "func_illusionary" || classname == "func_detail_illusionary") return BrushClass::NonSolid;
    return BrushClass::Solid;
}

bool isKnownClass(const std::string& c) {
    static const char* prefixes[] = {"func_", "trigger_", "info_player_", "light", "target_", "prop_"};
    for (const char* p : prefixes)
        if (startsWith(c, p)) return true;
    static const std::set<std::string> exact = {"worldspawn", "misc_model", "info_sign", "smoke_volume", "path_corner",
                                                "info_null", "info_notnull", "info_teleport_destination"};
    return exact.count(c) != 0;
}
}  // namespace

bool isInvisibleTexture(const std::string& texture) {
    const std::string t = lower(texture);
    return t.find("clip") != std::string::npos || t == "trigger" || t == "skip" || t == "hint" || t == "hintskip" ||
           t == "nodraw" || t == "caulk" || startsWith(t, "common/") || startsWith(t, "tools/");
}

bool isLiquidTexture(const std::string& texture) { return !texture.empty() && texture[0] == '*'; }

Level compileLevel(const MapFile& map, const CompileOptions& options, std::vector<std::string>* warnings) {
    Level level;
    level.sourcePath = map.path;
    auto warn = [&](const std::string& w) {
        if (warnings) warnings->push_back(w);
    };
    for (const auto& w : map.warnings) warn(w);

    double scale = options.unitsPerMetre;
    if (scale <= 0 && !map.entities.empty()) {
        const std::string& s = map.entities.front().value("units_per_metre");
        if (!s.empty()) {
            scale = std::atof(s.c_str());
            if (!(scale > 0)) warn(map.path + ": worldspawn units_per_metre '" + s + "' is not positive; using 32");
        }
    }
    if (!(scale > 0)) scale = kDefaultUnitsPerMetre;
    level.unitsPerMetre = scale;
    const double inv = 1.0 / scale;

    std::set<std::string> unknown;
    bool haveStart = false;
    int startPriority = 99;  // info_player_start beats deathmatch beats coop
    for (std::size_t ei = 0; ei < map.entities.size(); ++ei) {
        const MapEntity& me = map.entities[ei];
        LevelEntity e;
        e.keys = me.keys;
        e.pos = me.pos;
        e.classname = me.value("classname");
        e.isBrushEntity = !me.brushes.empty();
        Vec3 o;
        if (parseVec(me.value("origin"), o)) {
            e.hasOrigin = true;
            e.origin = toWorld(o) * inv;
        }
        double angleDeg = 0;
        Vec3 angles;
        if (parseVec(me.value("angles"), angles)) angleDeg = angles.y;
        else if (!me.value("angle").empty()) angleDeg = std::atof(me.value("angle").c_str());
        if (angleDeg == -1 || angleDeg == -2) angleDeg = 0;  // Quake's "up"/"down" specials
        e.yaw = angleDeg * kPi / 180.0 - kPi / 2.0;

        if (!isKnownClass(e.classname) && unknown.insert(e.classname).second) level.unknownClassnames.push_back(e.classname);

        const int entityIndex = static_cast<int>(ei);
        const std::string& c = e.classname;
        const int priority = c == "info_player_start" ? 0 : c == "info_player_deathmatch" ? 1 : c == "info_player_coop" ? 2 : 99;
        if (priority < startPriority && e.hasOrigin) {
            startPriority = priority;
            haveStart = true;
            level.playerStart = toWorld(o - Vec3{0, 0, kPlayerOriginAboveFeet}) * inv;
            level.playerStartYaw = e.yaw;
        }
        if (startsWith(c, "light") && e.hasOrigin) {
            LevelLight l;
            l.position = e.origin;
            const std::string& lv = me.value("light").empty() ? me.value("_light") : me.value("light");
            if (!lv.empty()) l.intensity = std::atof(lv.c_str());
            Vec3 col;
            const std::string& cs = me.value("_color").empty() ? me.value("color") : me.value("_color");
            if (parseVec(cs, col)) {
                if (col.x > 1 || col.y > 1 || col.z > 1) col = col / 255.0;
                l.colour = col;
            }
            l.radius = std::fabs(l.intensity) * inv;
            level.lights.push_back(l);
        }
        if (c == "misc_model") {
            LevelModel m;
            m.mesh = me.value("model");
            m.origin = e.origin;
            m.yaw = e.yaw + kPi / 2.0;  // models face +X in their own frame, as Quake models do
            const std::string& sc = me.value("scale").empty() ? me.value("modelscale") : me.value("scale");
            m.scale = sc.empty() ? 1.0 : std::atof(sc.c_str());
            m.entityIndex = entityIndex;
            if (m.mesh.empty()) warn(map.path + ":" + std::to_string(me.pos.line) + ": misc_model without a 'model' key");
            else level.models.push_back(m);
        }

        const BrushClass bc = classify(c);
        for (const MapBrush& mb : me.brushes) {
            BrushResult br = buildBrush(mb);
            if (!br.error.empty()) {
                warn(map.path + ":" + std::to_string(mb.pos.line) + ": brush skipped: " + br.error);
                continue;
            }
            LevelBrush b;
            b.entityIndex = entityIndex;
            b.pos = mb.pos;
            b.solid = bc == BrushClass::Solid;
            bool anyVisible = false;
            for (const BrushPolygon& bp : br.polygons) {
                const MapFace& face = mb.faces[static_cast<std::size_t>(bp.faceIndex)];
                LevelPolygon poly;
                poly.texture = face.texture;
                poly.normal = toWorld(bp.normal);
                poly.visible = bc != BrushClass::Trigger && !isInvisibleTexture(face.texture);
                if (isLiquidTexture(face.texture)) b.solid = false;
                int tw = 64, th = 64;
                if (options.textureSize) std::tie(tw, th) = options.textureSize(face.texture);
                for (std::size_t k = 0; k < bp.points.size(); ++k) {
                    LevelVertex v;
                    v.position = toWorld(bp.points[k]) * inv;
                    v.normal = poly.normal;
                    v.u = bp.u[k] / tw;
                    v.v = bp.v[k] / th;
                    poly.vertices.push_back(v);
                    b.bounds.extend(v.position);
                    bool dup = false;
                    for (const auto& h : b.hullPoints) dup |= length(h - v.position) < 1e-6;
                    if (!dup) b.hullPoints.push_back(v.position);
                }
                anyVisible |= poly.visible;
                b.faces.push_back(std::move(poly));
            }
            b.visible = anyVisible;
            level.bounds.extend(b.bounds.min);
            level.bounds.extend(b.bounds.max);
            level.brushes.push_back(std::move(b));
        }
        level.entities.push_back(std::move(e));
    }
    level.hasPlayerStart = haveStart;
    if (!haveStart) warn(map.path + ": no info_player_start; the player starts at the origin");
    return level;
}

Level loadLevel(const std::string& path, const CompileOptions& options, std::vector<std::string>* warnings) {
    return compileLevel(loadMapFile(path), options, warnings);
}

}  // namespace obscura::map
