// See entity_keys.h.
#include "sim/entity_keys.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace obscura::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

void EntityKeys::warn(const map::LevelEntity& e, const std::string& text) const {
    const std::string file = level_.sourcePath.empty() ? std::string("<level>") : level_.sourcePath;
    warnings_.push_back(file + ":" + std::to_string(e.pos.line) + ": " + (e.classname.empty() ? "entity" : e.classname) + ": " + text);
}

bool EntityKeys::leadingNumber(const std::string& s, double& out) const {
    const char* p = s.data();
    const char* const end = p + s.size();
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    if (p < end && *p == '+') ++p;
    const auto r = std::from_chars(p, end, out);  // locale-free
    return r.ec == std::errc() && std::isfinite(out);
}

double EntityKeys::number(const map::LevelEntity& e, const char* key, double fallback) const {
    if (!e.has(key)) return fallback;
    const std::string& s = e.value(key);
    double v = 0;
    if (leadingNumber(s, v)) return v;
    std::ostringstream os;
    os << "'" << key << "' value '" << s << "' is not a number; using " << fallback;
    warn(e, os.str());
    return fallback;
}

double EntityKeys::positive(const map::LevelEntity& e, const char* key, double fallback) const {
    const double v = number(e, key, 0);
    if (v > 0) return v;
    if (v < 0) {
        std::ostringstream os;
        os << "'" << key << "' value '" << e.value(key) << "' is negative; using " << fallback;
        warn(e, os.str());
    }
    return fallback;
}

Vec3 EntityKeys::moveDirection(const map::LevelEntity& e) const {
    double pitch = 0, yaw = 0;
    if (e.has("angles")) {
        std::istringstream is(e.value("angles"));
        is.imbue(std::locale::classic());
        if (!(is >> pitch >> yaw)) {
            warn(e, "'angles' value '" + e.value("angles") + "' is not \"pitch yaw roll\"; using 0 0 0");
            pitch = yaw = 0;
        }
    } else {
        yaw = number(e, "angle", 0);
    }
    // SetMovedir's specials: angles '0 -1 0' (or angle -1) is up, '0 -2 0' down.
    if (pitch == 0 && yaw == -1) return {0, 1, 0};
    if (pitch == 0 && yaw == -2) return {0, -1, 0};
    const double p = pitch * kPi / 180, y = yaw * kPi / 180;
    // makevectors: forward = (cos p cos y, cos p sin y, -sin p) in Quake's axes.
    return normalize(fromQuake(std::cos(p) * std::cos(y), std::cos(p) * std::sin(y), -std::sin(p)));
}

void EntityKeys::yawVectors(const map::LevelEntity& e, Vec3& forward, Vec3& right) const {
    double yaw = 0;
    if (e.has("angles")) {
        std::istringstream is(e.value("angles"));
        is.imbue(std::locale::classic());
        double pitch = 0;
        if (!(is >> pitch >> yaw)) yaw = 0;
    } else {
        yaw = number(e, "angle", 0);
    }
    const double y = yaw * kPi / 180;
    forward = fromQuake(std::cos(y), std::sin(y), 0);
    right = fromQuake(std::sin(y), -std::cos(y), 0);  // makevectors' v_right: forward turned 90 degrees clockwise
}

}  // namespace obscura::sim
