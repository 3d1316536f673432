// The decals in the world: a capped ring buffer (GoldSrc's mp_decals 300, Quake III's 256 mark
// polys), oldest recycled, and each decal's box as the shader reads it. Plain C++.
//
// A decal is a box: centre, the surface normal it is projected along (the box's z), a size across
// (x, y) and a depth (z), a rotation about the normal. Inside the box, the G-buffer's surfaces
// whose normal faces along +z take the decal.
#pragma once

#include "core/vec3.h"
#include "decals/decals_shared.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace obscura::decals {

struct Decal {
    Vec3 position;
    Vec3 normal{0, 1, 0};
    double width = 0.1, height = 0.1, depth = 0.1;  // metres, full sizes
    double angle = 0;                               // radians about the normal
    int tile = DECAL_TILE_BULLET;
    int style = 0;  // DECAL_STYLE_* bits
    double opacity = 1;
    bool tinted = false;  // colour (gamma, 0..1) replaces the tile's own (signs' _color)
    Vec3 colour{1, 1, 1};
};

// A decal box's frame: centre and unit axes (x, y across, z the projection axis = the normal;
// x and y from the normal alone, world up projected or world x on floors, turned by the angle).
struct BoxFrame {
    Vec3 centre, x, y, z;
};
BoxFrame boxFrame(const Decal& d);

// Empty when the decal can be drawn; else what is wrong, in words ("zero size", "non-finite ...").
std::string validate(const Decal& d);

// The DECAL_TEXELS x 4 floats the shader reads for a decal (decals_shared.h): three rows of the
// world -> box matrix (box = [-1, 1]^3), (tile, style, opacity, 0) and (colour, tinted).
std::array<float, DECAL_TEXELS * 4> packDecal(const Decal& d);

class DecalRing {
public:
    explicit DecalRing(int capacity);  // clamped to 1..DECAL_MAX_CAP
    // Adds `d` (the oldest one recycled when full); false (and nothing added) when invalid.
    bool add(const Decal& d);
    // The slot the next add() fills.
    int nextSlot() const { return next_; }
    // Slot `slot`'s decal moved (a decal on a prop following it); false (nothing changed) when
    // invalid or no such slot. Not a new decal: added() stays.
    bool replace(int slot, const Decal& d);
    void clear();
    int capacity() const { return capacity_; }
    int size() const { return static_cast<int>(slots_.size()); }
    // In slot order (slot i keeps its index until recycled).
    const std::vector<Decal>& slots() const { return slots_; }
    // Bumped on every change (the renderer uploads when it moves).
    std::uint64_t version() const { return version_; }
    // How many were ever added (deterministic per replay: the rotation's seed).
    std::uint64_t added() const { return added_; }

private:
    int capacity_;
    std::vector<Decal> slots_;
    int next_ = 0;
    std::uint64_t version_ = 0, added_ = 0;
};

// A bullet hole at an impact: the `n`th of the session (its rotation and size vary with n, the
// same in every replay).
Decal bulletHole(const Vec3& point, const Vec3& normal, std::uint64_t n);
// A scorch mark under a detonation at `point` (projected straight down).
Decal scorch(const Vec3& point, std::uint64_t n);

}  // namespace obscura::decals
