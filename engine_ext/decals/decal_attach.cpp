// See decal_attach.h.
#include "decals/decal_attach.h"

#include <algorithm>
#include <cmath>

namespace obscura::decals {

namespace {
bool finite(const BodyFrame& f) {
    return std::isfinite(f.position.x) && std::isfinite(f.position.y) && std::isfinite(f.position.z) && std::isfinite(f.qx) &&
           std::isfinite(f.qy) && std::isfinite(f.qz) && std::isfinite(f.qw);
}
}  // namespace

Vec3 rotate(const BodyFrame& f, const Vec3& v) {
    // v' = v + 2w (q x v) + 2 q x (q x v), q the vector part (unit quaternion).
    const Vec3 q{f.qx, f.qy, f.qz};
    const Vec3 t = cross(q, v) * 2.0;
    return v + t * f.qw + cross(q, t);
}

Vec3 rotateInverse(const BodyFrame& f, const Vec3& v) {
    BodyFrame c = f;
    c.qx = -f.qx;
    c.qy = -f.qy;
    c.qz = -f.qz;
    return rotate(c, v);
}

Vec3 toWorld(const BodyFrame& f, const Vec3& local) { return rotate(f, local) + f.position; }
Vec3 toLocal(const BodyFrame& f, const Vec3& world) { return rotateInverse(f, world - f.position); }

BoxFrame toLocal(const BodyFrame& body, const BoxFrame& world) {
    return {toLocal(body, world.centre), rotateInverse(body, world.x), rotateInverse(body, world.y), rotateInverse(body, world.z)};
}

BoxFrame toWorld(const BodyFrame& body, const BoxFrame& local) {
    return {toWorld(body, local.centre), rotate(body, local.x), rotate(body, local.y), rotate(body, local.z)};
}

Decal withFrame(Decal d, const BoxFrame& f) {
    d.position = f.centre;
    d.normal = normalize(f.z);
    // boxFrame's x is x0 cos(angle) + y0 sin(angle), x0 and y0 from the normal alone: read the
    // angle back from f.x in that basis (boxFrame's basis switches on floors; the angle follows).
    Decal unturned = d;
    unturned.angle = 0;
    const BoxFrame base = boxFrame(unturned);
    d.angle = std::atan2(dot(f.x, base.y), dot(f.x, base.x));
    return d;
}

DecalSet::DecalSet(int ringCapacity) : ring_(ringCapacity) {}

bool DecalSet::addFixed(const Decal& d) {
    if (!validate(d).empty()) return false;
    fixed_.push_back(d);
    rebuild();
    return true;
}

bool DecalSet::place(const Decal& d, const Slot& s) {
    const int slot = ring_.nextSlot();
    if (!ring_.add(d)) return false;
    if (slot >= static_cast<int>(slots_.size())) slots_.resize(static_cast<std::size_t>(slot) + 1);
    slots_[static_cast<std::size_t>(slot)] = s;  // a recycled slot forgets its old body
    rebuild();
    return true;
}

bool DecalSet::add(const Decal& d) { return place(d, Slot{}); }

bool DecalSet::addOn(const Decal& d, int body, const BodyFrame& pose) {
    if (body < 0 || !finite(pose) || !validate(d).empty()) return false;
    return place(d, Slot{body, toLocal(pose, boxFrame(d)), false});
}

void DecalSet::follow(const std::vector<BodyFrame>& poses) {
    bool changed = false;
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        Slot& s = slots_[i];
        if (s.body < 0 || s.dropped) continue;
        if (s.body >= static_cast<int>(poses.size()) || !finite(poses[static_cast<std::size_t>(s.body)])) {
            s.dropped = true;  // the body is gone: its decals with it
            changed = true;
            continue;
        }
        const Decal& now = ring_.slots()[i];
        const Decal moved = withFrame(now, toWorld(poses[static_cast<std::size_t>(s.body)], s.local));
        // A body at rest gives the same box again: no upload for sleeping props.
        if (moved.position == now.position && moved.normal == now.normal && moved.angle == now.angle) continue;
        if (ring_.replace(static_cast<int>(i), moved)) changed = true;
    }
    if (changed) rebuild();
}

int DecalSet::attachedCount() const {
    return static_cast<int>(std::count_if(slots_.begin(), slots_.end(), [](const Slot& s) { return s.body >= 0 && !s.dropped; }));
}

void DecalSet::rebuild() {
    list_ = fixed_;
    for (std::size_t i = 0; i < ring_.slots().size(); ++i)
        if (i >= slots_.size() || !slots_[i].dropped) list_.push_back(ring_.slots()[i]);
    ++version_;
}

}  // namespace obscura::decals
