// Decals that follow rigid bodies (a bullet hole on a crate stays on the crate when it is pushed,
// falls or tumbles), and the set of decals the game owns and pushes to rendering: fixed ones
// (signs, placed at load, never recycled), then the ring of bullet holes and scorch marks. Plain
// C++ (no OGRE, no Bullet): the game converts body poses at the boundary.
//
// A decal hit on a body keeps its box in the body's local frame (centre and the three box axes);
// every tick `follow` rebuilds the world box from the body's current pose, before the list goes
// to rendering. A body that is gone (no pose for it any more, or a non-finite one) drops its
// decals. Everything is in slot order: the same inputs give the same list in every replay.
#pragma once

#include "decals/decal_list.h"

#include <cstdint>
#include <vector>

namespace obscura::decals {

// A rigid body's pose: position and a unit quaternion (x, y, z, w), as Bullet gives them.
struct BodyFrame {
    Vec3 position;
    double qx = 0, qy = 0, qz = 0, qw = 1;
};

Vec3 rotate(const BodyFrame& f, const Vec3& v);         // by the quaternion
Vec3 rotateInverse(const BodyFrame& f, const Vec3& v);  // by its conjugate
Vec3 toWorld(const BodyFrame& f, const Vec3& local);
Vec3 toLocal(const BodyFrame& f, const Vec3& world);

// `d` with its centre, normal and angle set so that boxFrame() gives `f` (sizes, tile, style
// kept). f's axes must be orthonormal and right-handed (x cross y = z... as boxFrame gives them).
Decal withFrame(Decal d, const BoxFrame& f);

// The box in a body's frame (what a hit on the body stores).
BoxFrame toLocal(const BodyFrame& body, const BoxFrame& world);
BoxFrame toWorld(const BodyFrame& body, const BoxFrame& local);

class DecalSet {
public:
    // ringCapacity: the bullet holes' and scorch marks' cap (DecalRing); fixed decals beyond it.
    explicit DecalSet(int ringCapacity);

    // A decal that never moves and is never recycled (a sign); false if invalid.
    bool addFixed(const Decal& d);
    // A decal in the ring, in world space; false if invalid.
    bool add(const Decal& d);
    // A decal in the ring on body `body` (an index into the poses `follow` gets), whose pose is
    // `pose` now; false if invalid (or the pose non-finite).
    bool addOn(const Decal& d, int body, const BodyFrame& pose);
    // Every tick: decals on bodies follow poses[body]; a body beyond the list or with a
    // non-finite pose drops its decals (for good).
    void follow(const std::vector<BodyFrame>& poses);

    // Fixed decals, then the ring's live slots in slot order (dropped ones left out).
    const std::vector<Decal>& list() const { return list_; }
    // Bumped whenever list() changes (the renderer uploads when it moves).
    std::uint64_t version() const { return version_; }
    const DecalRing& ring() const { return ring_; }
    int fixedCount() const { return static_cast<int>(fixed_.size()); }
    // The most decals list() can hold: the ring's cap and the fixed ones.
    int capacity() const { return ring_.capacity() + fixedCount(); }
    // Decals now following a body.
    int attachedCount() const;

private:
    struct Slot {
        int body = -1;  // -1: world space
        BoxFrame local;
        bool dropped = false;
    };
    bool place(const Decal& d, const Slot& s);
    void rebuild();

    std::vector<Decal> fixed_;
    DecalRing ring_;
    std::vector<Slot> slots_;  // parallel to ring_.slots()
    std::vector<Decal> list_;
    std::uint64_t version_ = 0;
};

}  // namespace obscura::decals
