// The order OGRE draws a render queue's passes in, as a function of names only.
//
// OGRE groups a queue's solid renderables by Pass::getHash() and, where two passes hash alike,
// by their Pass* addresses (RenderQueueSortingGrouping.h, PassGroupLess). Its default hash reads
// the first two texture units' names; every cloned level material's G-buffer pass hashed alike
// (219535268 for brick, concrete and tile_floor on tests/sim/levels/pool.map), so their draw order
// followed the heap. Where two brushes meet, the face one brush hides under the other ties in depth
// with the visible one, and the pass drawn first wins the pixel: a run that baked the light (its
// worker threads leave the heap in another state) drew a different pixel from a run that read the
// bake from the cache (replay_pool_swim's `above`, 1 pixel by 71 levels, in CI, and in 1 of 2
// runs that baked under load here).
//
// The key: the pass's index in its technique in the top 4 bits (as OGRE's own: a material's first
// passes draw before its later ones) and 28 bits of the project's FNV-1a (core/state_hash.h) over
// the material's, scheme's and technique's names, so the order is the same in every run and the
// passes of one material stay together. Two names colliding in
// 28 bits (about 1 in 50,000 for a level's hundred materials) fall back to OGRE's address order.
#pragma once

#include "core/state_hash.h"

#include <cstdint>
#include <string_view>

namespace obscura::render {

inline std::uint32_t passOrderKey(std::string_view material, std::string_view scheme, std::string_view technique,
                                  unsigned passIndex) {
    StateHasher h;  // each name with its length: "ab"+"c" and "a"+"bc" differ
    h.add(material);
    h.add(scheme);
    h.add(technique);
    constexpr unsigned kIndexBits = 4;  // OGRE's own hash keeps the pass index in its top 4 bits
    constexpr std::uint32_t kNameMask = (1u << (32 - kIndexBits)) - 1;
    const auto index = static_cast<std::uint32_t>(passIndex & ((1u << kIndexBits) - 1));
    return (index << (32 - kIndexBits)) | (static_cast<std::uint32_t>(h.value()) & kNameMask);
}

}  // namespace obscura::render
