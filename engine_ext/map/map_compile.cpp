// See map_compile.h.
#include "map/map_compile.h"

#include "map/brush_geometry.h"
#include "map/entity_classes.h"
#include "map/input_file.h"
#include "map/surface_rules.h"
#include "map/liquid.h"
#include "map/map_lights.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>

namespace obscura::map {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Quake's default units per metre: the player is 56 units tall, about 1.75 m.
constexpr double kDefaultUnitsPerMetre = 32.0;
// info_player_start's origin is the player's centre, 24 units above the feet (Quake's hull).
constexpr double kPlayerOriginAboveFeet = 24.0;
constexpr int kNoStart = 99;  // startPriority of a class that is no player start

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}
bool startsWith(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

// Quake (x, y, z) -> Y-up (x, z, -y): a rotation, so windings and normals stay consistent.
Vec3 toWorld(const Vec3& q) { return {q.x, q.z, -q.y}; }

// Reads exactly `n` blank-separated numbers from a key value (locale-free, like the parser).
bool parseNumbers(const std::string& s, double* out, int n) {
    const char* p = s.data();
    const char* const end = s.data() + s.size();
    for (int k = 0; k < n; ++k) {
        while (p < end && (*p == ' ' || *p == '\t')) ++p;
        if (p < end && *p == '+') ++p;
        const auto r = std::from_chars(p, end, out[k]);
        if (r.ec != std::errc() || !std::isfinite(out[k])) return false;
        p = r.ptr;
    }
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    return p == end;
}
bool parseVec(const std::string& s, Vec3& out) {
    double v[3];
    if (!parseNumbers(s, v, 3)) return false;
    out = {v[0], v[1], v[2]};
    return true;
}

std::string shortNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.15g", v);
    return buf;
}

}  // namespace

Aabb placementRegion(const Level& level) {
    Aabb a;
    if (level.bounds.empty()) {
        a.min = a.max = Vec3{0, 0, 0};
    } else {
        a = level.bounds;
    }
    const Vec3 m{kPlacementMargin, kPlacementMargin, kPlacementMargin};
    a.min = a.min - m;
    a.max = a.max + m;
    return a;
}

bool inside(const Aabb& box, const Vec3& p) {
    return p.x >= box.min.x && p.x <= box.max.x && p.y >= box.min.y && p.y <= box.max.y && p.z >= box.min.z && p.z <= box.max.z;
}

namespace {
std::string describeOutside(const Aabb& box, const Vec3& p) {
    const auto v = [](const Vec3& q) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", q.x + 0.0, q.y + 0.0, q.z + 0.0);  // no "-0"
        return std::string(buf);
    };
    return v(p) + " m in the world, outside the level's brushes plus " + shortNumber(kPlacementMargin) + " m " + v(box.min) +
           " to " + v(box.max);
}

// What an entity's brushes become: the registry's answer for a known class. An unknown brush
// entity (a mod's func_ or trigger_ class) keeps Quake's convention so a foreign map still plays:
// trigger_* stays an invisible volume, anything else is solid world.
BrushRole brushRole(const EntityClass* known, const std::string& classname) {
    if (known) return known->brushes;
    return startsWith(classname, "trigger_") ? BrushRole::Volume : BrushRole::Solid;
}

// Spawn preference (lower wins; the first of equals wins), as Quake 2's SelectSpawnPoint for a
// fresh start: an unnamed info_player_start, else a named one (a level-transition start), else
// deathmatch, else coop.
int startPriority(const std::string& classname, const MapEntity& e) {
    if (classname == "info_player_start") return e.value("targetname").empty() ? 0 : 1;
    if (classname == "info_player_deathmatch") return 2;
    if (classname == "info_player_coop") return 3;
    return kNoStart;
}
}  // namespace

bool isInvisibleTexture(const std::string& texture) { return toolSurface(texture) != ToolSurface::None; }

bool isLiquidTexture(const std::string& texture) { return !texture.empty() && texture[0] == '*'; }

bool isMoverClass(const std::string& c) {
    return c == "func_door" || c == "func_door_secret" || c == "func_plat" || c == "func_button" || c == "func_train";
}

namespace {
// Compiles one entity: its point-entity meaning (player start, model) and its brushes (lights: map_lights.cpp).
class EntityCompiler {
public:
    EntityCompiler(const MapFile& map, const CompileOptions& options, Level& level, std::vector<std::string>* warnings)
        : map_(map), options_(options), level_(level), warnings_(warnings), inv_(1.0 / level.unitsPerMetre) {}

    void warn(const std::string& w) const {
        if (warnings_) warnings_->push_back(w);
    }
    void warnAt(const SourcePos& at, const std::string& w) const { warn(map_.path + ":" + std::to_string(at.line) + ": " + w); }

    // A numeric key of `e`, or `fallback` (with a warning naming the entity) when present but not
    // a number. Like Quake's atof, a leading number followed by more text counts (e3m4 has
    // "angle" "-30 0 0"; Quake turns `angle` into "0 <value> 0" and reads the yaw from it).
    double number(const MapEntity& e, const std::string& key, double fallback) const {
        const std::string& s = e.value(key);
        if (s.empty()) return fallback;
        const char* p = s.data();
        const char* const end = p + s.size();
        while (p < end && (*p == ' ' || *p == '\t')) ++p;
        if (p < end && *p == '+') ++p;
        double v = fallback;
        const auto r = std::from_chars(p, end, v);
        if (r.ec == std::errc() && std::isfinite(v)) return v;
        warnAt(e.pos, "'" + key + "' value '" + s + "' is not a number; using " + std::to_string(fallback));
        return fallback;
    }
    // `spawnflags` as Quake's progs test it (a float's integer part); a bad value is warned about
    // where the entity is spawned (game/sim/entity_keys.h), here it keeps the entity.
    static int spawnflags(const MapEntity& e) {
        const std::string& s = e.value("spawnflags");
        const char* p = s.data();
        while (p < s.data() + s.size() && (*p == ' ' || *p == '\t')) ++p;
        double v = 0;
        const auto r = std::from_chars(p, s.data() + s.size(), v);
        return r.ec == std::errc() && v >= 0 && v < 2147483648.0 ? static_cast<int>(v) : 0;
    }
    bool vec(const MapEntity& e, const std::string& key, Vec3& out) const {
        const std::string& s = e.value(key);
        if (s.empty()) return false;
        if (parseVec(s, out)) return true;
        warnAt(e.pos, "'" + key + "' value '" + s + "' is not three numbers; ignored");
        return false;
    }

    void compile(std::size_t index) {
        const MapEntity& me = map_.entities[index];
        if (index > 0 && leftOutAtSkill(spawnflags(me), options_.skill)) {  // never worldspawn, as Quake
            ++level_.leftOutEntities;
            return;
        }
        LevelEntity e;
        e.keys = me.keys;
        e.pos = me.pos;
        e.file = me.file;
        e.classname = me.value("classname");
        e.isBrushEntity = !me.brushes.empty();
        Vec3 quakeOrigin;
        if (vec(me, "origin", quakeOrigin)) {
            e.hasOrigin = true;
            e.origin = toWorld(quakeOrigin) * inv_;
        }
        double angleDeg = 0;
        Vec3 angles;
        if (vec(me, "angles", angles)) angleDeg = angles.y;  // pitch yaw roll
        else angleDeg = number(me, "angle", 0);
        if (angleDeg == -1 || angleDeg == -2) angleDeg = 0;  // Quake's "up"/"down" specials
        e.yaw = angleDeg * kPi / 180.0 - kPi / 2.0;

        const std::string& c = e.classname;
        const EntityClass* known = findEntityClass(c);
        if (c.empty()) warnAt(me.pos, "entity without a classname");
        else if (!known) countUnknown(c);

        const int priority = startPriority(c, me);
        if (priority < startPriority_ && e.hasOrigin) {
            startPriority_ = priority;
            level_.hasPlayerStart = true;
            level_.playerStart = toWorld(quakeOrigin - Vec3{0, 0, kPlayerOriginAboveFeet}) * inv_;
            level_.playerStartYaw = e.yaw;
        }
        const int levelIndex = static_cast<int>(level_.entities.size());  // entities left out leave no gap
        if (known && known->role == EntityRole::Model) addModel(me, e, levelIndex);
        current_ = e;  // its keys, for the liquid alpha of its brushes (pushed after them)
        for (const MapBrush& mb : me.brushes) addBrush(mb, brushRole(known, c), levelIndex, isMoverClass(c));
        level_.entities.push_back(std::move(e));
    }

private:
    void countUnknown(const std::string& c) {
        auto& names = level_.unknownClassnames;
        const auto at = std::find(names.begin(), names.end(), c);
        if (at != names.end()) {
            ++level_.unknownClassCounts[static_cast<std::size_t>(at - names.begin())];
            return;
        }
        names.push_back(c);
        level_.unknownClassCounts.push_back(1);
    }

    [[noreturn]] void failAt(const SourcePos& at, const std::string& problem) const {
        throw MapError(map_.path + ":" + std::to_string(at.line) + ": " + problem);
    }

    void addModel(const MapEntity& me, const LevelEntity& e, int entityIndex) {
        LevelModel m;
        m.mesh = me.value("model");
        m.origin = e.origin;
        m.yaw = e.yaw + kPi / 2.0;  // models face +X in their own frame, as Quake models do
        // The scale reaches OGRE as a float node scale and divides in its bounds: it must be a
        // finite number in [kMinModelScale, kMaxModelScale] (0, a denormal or 1e39 would assert).
        const char* scaleKey = me.has("scale") ? "scale" : "modelscale";
        const std::string& scaleText = me.value(scaleKey);
        if (!scaleText.empty()) {
            double v = 0;
            if (!parseNumbers(scaleText, &v, 1) || !(v >= kMinModelScale && v <= kMaxModelScale))
                failAt(me.pos, "misc_model '" + std::string(scaleKey) + "' value '" + errorText(scaleText) +
                                   "' is not a number from " + shortNumber(kMinModelScale) + " to " + shortNumber(kMaxModelScale));
            m.scale = v;
        }
        if (m.mesh.size() > kMaxModelName)
            failAt(me.pos, "misc_model 'model' value '" + errorText(m.mesh) + "' is longer than " + std::to_string(kMaxModelName) + " characters");
        m.entityIndex = entityIndex;
        m.pos = me.pos;
        if (m.mesh.empty()) warnAt(me.pos, "misc_model without a 'model' key");
        else level_.models.push_back(m);
    }

    std::pair<int, int> textureSize(const std::string& texture) const {
        // 64x64 by default (the most common Quake texture size); a non-positive answer falls back too.
        std::pair<int, int> size{64, 64};
        if (options_.textureSize) size = options_.textureSize(texture);
        if (size.first <= 0 || size.second <= 0) size = {64, 64};
        return size;
    }

    // ericw-tools' qbsp: a brush of hint faces (the rest skip) is a vis splitter, an origin brush
    // marks a rotator's centre, and a monster clip blocks monsters (Obscura has none): none of them
    // is drawn or collides. (Clip and all-skip brushes stay: solid, not drawn.)
    static bool isToolBrush(const MapBrush& mb) {
        bool hint = false, onlyHintOrSkip = true;
        for (const MapFace& f : mb.faces) {
            const ToolSurface t = toolSurface(f.texture, f.hasFlags, f.contents, f.surfaceFlags);
            if (t == ToolSurface::Origin || t == ToolSurface::MonsterClip) return true;
            hint = hint || t == ToolSurface::Hint;
            onlyHintOrSkip = onlyHintOrSkip && (t == ToolSurface::Hint || t == ToolSurface::Skip);
        }
        return hint && onlyHintOrSkip;
    }

    void addBrush(const MapBrush& mb, BrushRole role, int entityIndex, bool mover) {
        BrushResult br = buildBrush(mb);
        if (!br.error.empty()) {
            warnAt(mb.pos, "brush skipped: " + br.error);
            return;
        }
        if (isToolBrush(mb)) return;  // hint, origin and monster-clip brushes: no geometry for this game
        LevelBrush b;
        b.entityIndex = entityIndex;
        b.pos = mb.pos;
        b.solid = role == BrushRole::Solid;
        b.mover = mover;
        b.visible = false;
        double q2Alpha = 1;  // Quake 2 SURF_TRANS33/66 on a liquid face
        for (const BrushPolygon& bp : br.polygons) {
            const MapFace& face = mb.faces[static_cast<std::size_t>(bp.faceIndex)];
            LevelPolygon poly;
            poly.texture = face.texture;
            poly.normal = toWorld(bp.normal);
            poly.visible = role != BrushRole::Volume && toolSurface(face.texture, face.hasFlags, face.contents, face.surfaceFlags) == ToolSurface::None &&
                           !isLiquidSkipTexture(face.texture);
            poly.contents = face.contents;
            poly.surfaceFlags = face.surfaceFlags;
            poly.surfaceValue = face.value;
            poly.sky = isSkyFace(face.texture, face.surfaceFlags);
            poly.fence = isFenceTexture(face.texture);
            // A liquid face makes the brush a liquid volume (non-solid); Quake 2 content bits win
            // over the name (their liquids have no '*'). The most harmful face decides.
            const LiquidKind kind = face.hasFlags && liquidKindOfContents(face.contents) != LiquidKind::None
                                        ? liquidKindOfContents(face.contents)
                                        : liquidKindOfTexture(face.texture);
            if (kind != LiquidKind::None) {
                b.solid = false;
                if (liquidHarm(kind) > liquidHarm(b.liquid)) b.liquid = kind;
                if (face.hasFlags && (face.surfaceFlags & (kQ2SurfTrans33 | kQ2SurfTrans66)))
                    q2Alpha = std::min(q2Alpha, face.surfaceFlags & kQ2SurfTrans33 ? 0.33 : 0.66);
            }
            const auto [tw, th] = textureSize(face.texture);
            for (std::size_t k = 0; k < bp.points.size(); ++k) {
                LevelVertex v;
                v.position = toWorld(bp.points[k]) * inv_;
                v.normal = poly.normal;
                v.u = bp.u[k] / tw;
                v.v = bp.v[k] / th;
                poly.vertices.push_back(v);
                b.bounds.extend(v.position);
                // Faces share corners: keep each corner once (corners of one brush are far apart).
                bool dup = false;
                for (const auto& h : b.hullPoints) dup |= length(h - v.position) < kHullWeld;
                if (!dup) b.hullPoints.push_back(v.position);
            }
            b.visible |= poly.visible;
            b.faces.push_back(std::move(poly));
        }
        if (b.liquid != LiquidKind::None) {
            std::vector<LiquidKeyProblem> problems;
            const LevelEntity& owner = current_;  // (pushed to the level after its brushes)
            b.liquidAlpha = std::min(q2Alpha, liquidAlpha(worldspawn(), owner, b.liquid, &problems));
            for (const auto& p : problems)  // once per key, not per brush
                if (reported_.insert(std::to_string(p.at.line) + ":" + p.what).second) warnAt(p.at, p.what);
        }
        level_.bounds.extend(b.bounds.min);
        level_.bounds.extend(b.bounds.max);
        level_.brushes.push_back(std::move(b));
    }

    // The worldspawn's keys (the liquid alpha keys); an empty entity before it is compiled.
    const LevelEntity& worldspawn() const { return level_.entities.empty() ? current_ : level_.entities.front(); }

    // Corner welding distance for hullPoints, metres: far below any real brush feature, far above
    // the rounding of the clipped corners.
    static constexpr double kHullWeld = 1e-6;

    const MapFile& map_;
    const CompileOptions& options_;
    Level& level_;
    std::vector<std::string>* warnings_;
    double inv_;
    LevelEntity current_;             // the entity whose brushes are being compiled
    std::set<std::string> reported_;  // liquid alpha problems, once each
    int startPriority_ = kNoStart;
};
}  // namespace

Level compileLevel(const MapFile& map, const CompileOptions& options, std::vector<std::string>* warnings) {
    Level level;
    level.sourcePath = map.path;
    if (options.skill < kMinSkill || options.skill > kMaxSkill)
        throw MapError(map.path + ": skill " + std::to_string(options.skill) + " is out of range, expected " + std::to_string(kMinSkill) +
                       " to " + std::to_string(kMaxSkill));
    level.skill = options.skill;
    if (warnings) warnings->insert(warnings->end(), map.warnings.begin(), map.warnings.end());

    double scale = options.unitsPerMetre;
    if (scale != 0 && !(scale >= kMinUnitsPerMetre && scale <= kMaxUnitsPerMetre))
        throw MapError(map.path + ": units per metre " + shortNumber(scale) + " is out of range, expected " +
                       shortNumber(kMinUnitsPerMetre) + " to " + shortNumber(kMaxUnitsPerMetre));
    if (scale == 0 && !map.entities.empty()) {
        const std::string& s = map.entities.front().value("units_per_metre");
        if (!s.empty() && (!parseNumbers(s, &scale, 1) || !(scale >= kMinUnitsPerMetre && scale <= kMaxUnitsPerMetre)))
            throw MapError(map.path + ":" + std::to_string(map.entities.front().pos.line) + ": worldspawn 'units_per_metre' value '" +
                           errorText(s) + "' is not a number from " + shortNumber(kMinUnitsPerMetre) + " to " +
                           shortNumber(kMaxUnitsPerMetre));
    }
    if (scale == 0) scale = kDefaultUnitsPerMetre;
    level.unitsPerMetre = scale;

    EntityCompiler compiler(map, options, level, warnings);
    for (std::size_t i = 0; i < map.entities.size(); ++i) compiler.compile(i);
    hideBuriedLiquidFaces(level);  // a pool's sides and bottom against its walls are not drawn
    compileLights(level, map.path, warnings);  // after all entities: spotlights aim at any entity's origin
    if (!level.hasPlayerStart) compiler.warn(map.path + ": no info_player_start; the player starts at the origin");
    // Every placed thing within the level's box plus a margin: a player start or model far out
    // reaches OGRE's shadow camera as a degenerate box (an assertion), and is a broken level anyway.
    const Aabb allowed = placementRegion(level);
    for (const LevelEntity& e : level.entities)
        if (e.hasOrigin && !inside(allowed, e.origin))
            throw MapError(map.path + ":" + std::to_string(e.pos.line) + ": " + (e.classname.empty() ? "entity" : errorText(e.classname)) +
                           " origin '" + errorText(e.value("origin")) + "' is " + describeOutside(allowed, e.origin));
    return level;
}

Level loadLevel(const std::string& path, const CompileOptions& options, std::vector<std::string>* warnings) {
    return compileLevel(loadMapFile(path), options, warnings);
}

void addEntityOverlay(MapFile& map, const std::string& overlayPath) {
    MapFile overlay = loadMapFile(overlayPath);
    for (MapEntity& e : overlay.entities) {
        const std::string where = overlayPath + ":" + std::to_string(e.pos.line);
        if (e.value("classname") == "worldspawn") throw MapError(where + ": an entity overlay cannot hold a worldspawn");
        if (!e.brushes.empty()) throw MapError(where + ": an entity overlay holds point entities only, this one has brushes");
        e.file = overlayPath;
        map.entities.push_back(std::move(e));
    }
    for (auto& w : overlay.warnings) map.warnings.push_back(std::move(w));
}

}  // namespace obscura::map
