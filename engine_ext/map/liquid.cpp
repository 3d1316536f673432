// See liquid.h.
#include "map/liquid.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace obscura::map {

namespace {
std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}
bool has(const std::string& s, const char* part) { return s.find(part) != std::string::npos; }

}  // namespace

int liquidHarm(LiquidKind k) {
    switch (k) {
        case LiquidKind::Lava: return 4;
        case LiquidKind::Slime: return 3;
        case LiquidKind::Water: return 2;
        case LiquidKind::Teleport: return 1;
        case LiquidKind::None: break;
    }
    return 0;
}

namespace {
// A face's point nudged this far out of it decides whether the face is buried in a solid: well
// above the compiler's 1e-3-unit plane epsilon, below any wall (a Quake wall is >= 1 unit, 3 cm).
constexpr double kBuriedProbe = 0.01;
// A point this close outside a plane still counts as inside (metres): float noise of the corners.
constexpr double kPlaneEpsilon = 1e-6;
}  // namespace

LiquidKind liquidKindOfTexture(const std::string& texture) {
    if (texture.empty() || texture[0] != '*') return LiquidKind::None;
    const std::string t = lower(texture);
    if (has(t, "slime")) return LiquidKind::Slime;
    if (has(t, "lava")) return LiquidKind::Lava;
    if (has(t, "tele")) return LiquidKind::Teleport;
    return LiquidKind::Water;
}

LiquidKind liquidKindOfContents(std::uint32_t q2Contents) {
    if (q2Contents & kQ2ContentsLava) return LiquidKind::Lava;
    if (q2Contents & kQ2ContentsSlime) return LiquidKind::Slime;
    if (q2Contents & kQ2ContentsWater) return LiquidKind::Water;
    return LiquidKind::None;
}

bool isLiquidSkipTexture(const std::string& texture) {
    const std::string t = lower(texture);
    return t == "*skip" || t == "*waterskip" || t == "*slimeskip" || t == "*lavaskip" || t == "*teleskip";
}

const char* liquidName(LiquidKind kind) {
    switch (kind) {
        case LiquidKind::Water: return "water";
        case LiquidKind::Slime: return "slime";
        case LiquidKind::Lava: return "lava";
        case LiquidKind::Teleport: return "tele";
        case LiquidKind::None: break;
    }
    return "none";
}

std::optional<double> liquidAlphaKey(const LevelEntity& entity, const std::string& key, std::string* problem) {
    for (const std::string& name : {"_" + key, key}) {
        if (!entity.has(name)) continue;
        const std::string& s = entity.value(name);
        const char* p = s.data();
        const char* const end = p + s.size();
        while (p < end && (*p == ' ' || *p == '\t')) ++p;
        double v = 0;
        const auto r = std::from_chars(p, end, v);
        const char* q = r.ptr;
        while (q < end && (*q == ' ' || *q == '\t')) ++q;
        if (r.ec == std::errc() && q == end && v >= 0 && v <= 1) return v;
        if (problem) *problem = "'" + name + "' value '" + s + "' is not a number from 0 to 1; ignored";
        return std::nullopt;
    }
    return std::nullopt;
}

double liquidAlpha(const LevelEntity& worldspawn, const LevelEntity& owner, LiquidKind kind, std::vector<LiquidKeyProblem>* problems) {
    const auto read = [&](const LevelEntity& e, const std::string& key) {
        std::string problem;
        const auto v = liquidAlphaKey(e, key, &problem);
        if (!problem.empty() && problems) problems->push_back({e.pos, problem});
        return v;
    };
    const std::string own = std::string(liquidName(kind)) + "alpha";
    // An entity's liquid keys: the kind's own, else water's.
    const auto liquidKeys = [&](const LevelEntity& e) -> std::optional<double> {
        if (kind != LiquidKind::Water)
            if (const auto v = read(e, own)) return v;
        return read(e, "wateralpha");
    };
    // A brush entity's `alpha`, then its own liquid keys (a func_water with `_wateralpha`), then
    // worldspawn's.
    if (&owner != &worldspawn) {
        if (const auto v = read(owner, "alpha")) return *v;
        if (const auto v = liquidKeys(owner)) return *v;
    }
    if (const auto v = liquidKeys(worldspawn)) return *v;
    return 1.0;
}

bool pointInBrush(const LevelBrush& brush, const Vec3& p) {
    if (brush.faces.empty() || brush.bounds.empty()) return false;
    const Aabb& b = brush.bounds;
    if (p.x < b.min.x - kPlaneEpsilon || p.y < b.min.y - kPlaneEpsilon || p.z < b.min.z - kPlaneEpsilon ||
        p.x > b.max.x + kPlaneEpsilon || p.y > b.max.y + kPlaneEpsilon || p.z > b.max.z + kPlaneEpsilon)
        return false;
    for (const LevelPolygon& f : brush.faces) {
        if (f.vertices.empty()) continue;
        if (dot(p - f.vertices[0].position, f.normal) > kPlaneEpsilon) return false;
    }
    return true;
}

LiquidQuery::LiquidQuery(const Level& level) {
    for (const LevelBrush& b : level.brushes) {
        if (b.liquid == LiquidKind::None || b.faces.empty()) continue;
        Volume v{b.liquid, b.bounds, {}};
        for (const LevelPolygon& f : b.faces)
            if (!f.vertices.empty()) v.planes.push_back({f.normal, dot(f.normal, f.vertices[0].position)});
        volumes_.push_back(std::move(v));
    }
}

LiquidKind LiquidQuery::at(const Vec3& p) const {
    LiquidKind best = LiquidKind::None;
    for (const Volume& v : volumes_) {
        if (liquidHarm(v.kind) <= liquidHarm(best)) continue;
        const Aabb& b = v.bounds;
        if (p.x < b.min.x || p.y < b.min.y || p.z < b.min.z || p.x > b.max.x || p.y > b.max.y || p.z > b.max.z) continue;
        bool inside = true;
        for (const Plane& pl : v.planes) inside = inside && dot(pl.normal, p) <= pl.dist + kPlaneEpsilon;
        if (inside) best = v.kind;
    }
    return best;
}

std::size_t hideBuriedLiquidFaces(Level& level) {
    std::vector<const LevelBrush*> solids;
    for (const LevelBrush& b : level.brushes)
        if (b.solid && b.entityIndex == 0 && b.liquid == LiquidKind::None) solids.push_back(&b);
    std::size_t hidden = 0;
    for (LevelBrush& b : level.brushes) {
        if (b.liquid == LiquidKind::None) continue;
        b.visible = false;
        for (LevelPolygon& f : b.faces) {
            if (f.visible && !f.vertices.empty()) {
                Vec3 c;
                for (const auto& v : f.vertices) c += v.position;
                c = c / static_cast<double>(f.vertices.size()) + f.normal * kBuriedProbe;
                for (const LevelBrush* s : solids)
                    if (pointInBrush(*s, c)) {
                        f.visible = false;
                        ++hidden;
                        break;
                    }
            }
            b.visible |= f.visible;
        }
    }
    return hidden;
}

}  // namespace obscura::map
