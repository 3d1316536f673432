// OGRE glue for render/pass_order_key.h: every Pass hashes by its material's, scheme's and
// technique's names, so the draw order within a render queue never depends on heap addresses.
// Installed once, before any material exists (a pass's hash is kept from when it was computed).
#pragma once

namespace obscura::render {

void installNamedPassOrder();

}  // namespace obscura::render
