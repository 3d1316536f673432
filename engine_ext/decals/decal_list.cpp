// See decal_list.h.
#include "decals/decal_list.h"

#include "core/rng.h"

#include <algorithm>
#include <cmath>

namespace obscura::decals {

namespace {
bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

std::string validate(const Decal& d) {
    if (!finite(d.position)) return "non-finite position";
    if (!finite(d.normal) || length(d.normal) < 1e-6) return "no usable normal";
    if (!std::isfinite(d.angle)) return "non-finite angle";
    if (!(d.width > 1e-4 && d.height > 1e-4 && d.depth > 1e-4) || !std::isfinite(d.width + d.height + d.depth))
        return "zero or non-finite size";
    if (d.tile < 0 || d.tile >= DECAL_MAX_TILES) return "no atlas tile " + std::to_string(d.tile);
    if (!std::isfinite(d.opacity)) return "non-finite opacity";
    if (d.tinted && !finite(d.colour)) return "non-finite colour";
    return {};
}

BoxFrame boxFrame(const Decal& d) {
    const Vec3 z = normalize(d.normal);
    // A tangent that does not depend on anything but the normal: world up projected, or world x
    // on floors and ceilings.
    const Vec3 ref = std::fabs(z.y) > 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 y0 = normalize(ref - z * dot(ref, z));
    const Vec3 x0 = cross(y0, z);
    const double c = std::cos(d.angle), s = std::sin(d.angle);
    return {d.position, x0 * c + y0 * s, y0 * c - x0 * s, z};
}

std::array<float, DECAL_TEXELS * 4> packDecal(const Decal& d) {
    const BoxFrame f = boxFrame(d);
    const Vec3 &x = f.x, &y = f.y, &z = f.z;
    std::array<float, DECAL_TEXELS * 4> out{};
    auto row = [&](int i, const Vec3& axis, double half) {
        const Vec3 a = axis * (1.0 / half);
        out[i * 4 + 0] = static_cast<float>(a.x);
        out[i * 4 + 1] = static_cast<float>(a.y);
        out[i * 4 + 2] = static_cast<float>(a.z);
        out[i * 4 + 3] = static_cast<float>(-dot(a, d.position));
    };
    row(0, x, d.width / 2);
    row(1, y, d.height / 2);
    row(2, z, d.depth / 2);
    out[12] = static_cast<float>(d.tile);
    out[13] = static_cast<float>(d.style);
    out[14] = static_cast<float>(std::clamp(d.opacity, 0.0, 1.0));
    out[16] = static_cast<float>(std::clamp(d.colour.x, 0.0, 1.0));
    out[17] = static_cast<float>(std::clamp(d.colour.y, 0.0, 1.0));
    out[18] = static_cast<float>(std::clamp(d.colour.z, 0.0, 1.0));
    out[19] = d.tinted ? 1.0f : 0.0f;
    return out;
}

DecalRing::DecalRing(int capacity) : capacity_(std::clamp(capacity, 1, DECAL_MAX_CAP)) {}

bool DecalRing::add(const Decal& d) {
    if (!validate(d).empty()) return false;
    if (static_cast<int>(slots_.size()) < capacity_) slots_.push_back(d);
    else slots_[static_cast<std::size_t>(next_)] = d;
    next_ = (next_ + 1) % capacity_;
    ++version_;
    ++added_;
    return true;
}

bool DecalRing::replace(int slot, const Decal& d) {
    if (slot < 0 || slot >= size() || !validate(d).empty()) return false;
    slots_[static_cast<std::size_t>(slot)] = d;
    ++version_;
    return true;
}

void DecalRing::clear() {
    slots_.clear();
    next_ = 0;
    ++version_;
}

Decal bulletHole(const Vec3& point, const Vec3& normal, std::uint64_t n) {
    Rng rng(0xdeca1ULL + n);
    Decal d;
    d.normal = normal;
    d.position = point;
    d.width = d.height = 0.07 + 0.03 * rng.uniform01d();  // 7-10 cm: the hole and its soot
    d.depth = 0.10;                                       // 5 cm either side of the surface
    d.angle = 6.283185307179586 * rng.uniform01d();
    d.tile = DECAL_TILE_BULLET;
    d.style = static_cast<int>(DECAL_STYLE_SMOOTH) | static_cast<int>(DECAL_STYLE_OUTLINE) | static_cast<int>(DECAL_STYLE_GLOW);
    return d;
}

Decal scorch(const Vec3& point, std::uint64_t n) {
    Rng rng(0x5c0cULL + n);
    Decal d;
    d.position = point;
    d.normal = {0, 1, 0};
    d.width = d.height = 1.6 + 0.4 * rng.uniform01d();
    d.depth = 1.2;
    d.angle = 6.283185307179586 * rng.uniform01d();
    d.tile = DECAL_TILE_SCORCH;
    d.style = static_cast<int>(DECAL_STYLE_SMOOTH) | static_cast<int>(DECAL_STYLE_GLOW);
    d.opacity = 0.85;
    return d;
}

}  // namespace obscura::decals
