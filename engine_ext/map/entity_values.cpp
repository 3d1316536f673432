// See entity_values.h.
#include "map/entity_values.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace obscura::map {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

std::vector<std::string> valueWords(const std::string& s) {
    std::vector<std::string> out;
    std::string w;
    for (char c : s + " ") {
        if (c == ' ' || c == '\t' || c == ',') {
            if (!w.empty()) out.push_back(w);
            w.clear();
        } else {
            w += c;
        }
    }
    return out;
}

bool valueNumbers(const std::string& text, std::size_t n, double* out) {
    const auto w = valueWords(text);
    if (w.size() != n) return false;
    for (std::size_t i = 0; i < n; ++i) {
        const char* end = w[i].data() + w[i].size();
        const auto [p, ec] = std::from_chars(w[i].data(), end, out[i]);
        if (ec != std::errc() || p != end) return false;
    }
    return true;
}

std::string quotedValue(const std::string& s) { return "'" + (s.size() > 64 ? s.substr(0, 64) + "..." : s) + "'"; }

std::string messageText(const std::string& value) {
    std::string out;
    for (std::size_t i = 0; i < value.size(); ++i) {
        if (value[i] == '\\' && i + 1 < value.size() && value[i + 1] == 'n') {
            out += '\n';
            ++i;
        } else {
            out += value[i];
        }
    }
    return out;
}

Vec3 mapPointToWorld(const Vec3& q, double unitsPerMetre) { return Vec3{q.x, q.z, -q.y} * (1.0 / unitsPerMetre); }

std::string readOrigin(const LevelEntity& e, Vec3& out) {
    double v[3];
    if (!e.has("origin")) return "no 'origin'";
    const bool parsed = valueNumbers(e.value("origin"), 3, v);
    if (parsed && !std::isfinite(v[0] + v[1] + v[2])) return "non-finite origin " + quotedValue(e.value("origin"));
    if (!parsed || !e.hasOrigin || !std::isfinite(e.origin.x + e.origin.y + e.origin.z))
        return "'origin' is " + quotedValue(e.value("origin")) + ", expected three numbers";
    out = e.origin;
    return "";
}

std::string readOrientation(const LevelEntity& e, Orientation& out) {
    double pitch = 0, yaw = 0, roll = 0;
    if (e.has("mangle")) {
        double a[3];
        if (!valueNumbers(e.value("mangle"), 3, a))
            return "'mangle' is " + quotedValue(e.value("mangle")) + ", expected \"pitch yaw roll\" in degrees";
        if (!std::isfinite(a[0] + a[1] + a[2])) return "non-finite mangle " + quotedValue(e.value("mangle"));
        pitch = a[0], yaw = a[1], roll = a[2];
    } else if (e.has("angle")) {
        if (!valueNumbers(e.value("angle"), 1, &yaw)) return "'angle' is " + quotedValue(e.value("angle")) + ", expected degrees";
        if (!std::isfinite(yaw)) return "non-finite angle " + quotedValue(e.value("angle"));
    }
    // Quake axes (x east, y north, z up) to ours: (x, z, -y).
    const double p = pitch * kPi / 180, y = yaw * kPi / 180, r = roll * kPi / 180;
    const Vec3 flat{std::cos(y), 0, -std::sin(y)}, worldUp{0, 1, 0};
    const Vec3 right0{-std::sin(y), 0, -std::cos(y)};  // cross(worldUp, flat)
    // Pitch tips the facing down (positive) and the up with it, about the right.
    const Vec3 facing = flat * std::cos(p) - worldUp * std::sin(p);
    const Vec3 up1 = flat * std::sin(p) + worldUp * std::cos(p);
    const double c = std::cos(r), s = std::sin(r);
    out.facing = facing;
    out.right = right0 * c + up1 * s;
    out.up = up1 * c - right0 * s;
    out.roll = r;
    return "";
}

std::string readColour(const LevelEntity& e, const std::string& key, Vec3& out) {
    if (!e.has(key)) return "";
    double c[3];
    if (!valueNumbers(e.value(key), 3, c) || !std::isfinite(c[0] + c[1] + c[2]))
        return "'" + key + "' is " + quotedValue(e.value(key)) + ", expected \"r g b\"";
    const double scale = std::max({c[0], c[1], c[2]}) > 1 ? 255.0 : 1.0;
    for (double x : c)
        if (x < 0 || x > scale) return "'" + key + "' " + quotedValue(e.value(key)) + " is outside 0..1 (or 0..255)";
    out = {c[0] / scale, c[1] / scale, c[2] / scale};
    return "";
}

}  // namespace obscura::map
