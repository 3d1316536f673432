// Conversions between the plain-C++ core's types and OGRE's (both Y up, right-handed, metres).
#pragma once

#include <OgreVector.h>

#include "core/vec3.h"

namespace obscura::render {

inline Ogre::Vector3 toOgre(const Vec3& v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

inline Vec3 fromOgre(const Ogre::Vector3& v) { return {v.x, v.y, v.z}; }

}  // namespace obscura::render
