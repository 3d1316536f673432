// What the decal baker (engine_ext/decals, tools/decalbake), the decal renderer and its GLSL
// (shaders/decals) agree on: plain #defines valid in C++ and GLSL.
#ifndef OBSCURA_DECALS_SHARED_H
#define OBSCURA_DECALS_SHARED_H

// The atlas (build/generated/textures/decal_atlas.png): DECAL_TILES square tiles of DECAL_TILE
// texels side by side. RGB: the multi-channel field (median = the shape with sharp corners; the
// same value thrice for a mask without an outline); A: the true signed distance (exact EDT).
// Texel value 0.5 = the edge, 0.5 + d / (2 DECAL_RANGE) at d texels inside.
#define DECAL_TILE 64
#define DECAL_RANGE 4.0
#define DECAL_BAKE_FACTOR 16  // the mask is DECAL_TILE x DECAL_BAKE_FACTOR on a side (1024^2)
#define DECAL_TILE_BULLET 0   // a hole with a cracked rim
#define DECAL_TILE_SCORCH 1   // an irregular blot, drawn soft (the glow option)
#define DECAL_TILE_SIGN 2     // text from a font (multi-channel)
#define DECAL_TILE_SQUARE 3   // a square plate (multi-channel: sharp corners)
#define DECAL_TILES 4          // the tiles baked at build time
// Signs (decal_sign in a .map) get tiles of their own, baked at level load after the build's:
// the atlas in use is DECAL_TILES + that many tiles wide (uniform atlasTiles), at most
// DECAL_MAX_TILES: 32 x 64 = 2048 texels, the width every GL 3.3 driver we met takes.
#define DECAL_MAX_TILES 32

// Per-decal data: DECAL_TEXELS RGBA32F texels a decal in a DECAL_TEXELS x cap data texture.
//   0..2: rows of the world -> decal-box matrix (box = [-1, 1]^3, projection along the box's z)
//   3: (tile, style, opacity, 0)
//   4: (tint r, g, b, tinted): a sign's colour (gamma) replaces its tile's own when tinted > 0.5
#define DECAL_TEXELS 5
// Styles (combinable bits): how the field becomes coverage and colour.
#define DECAL_STYLE_SMOOTH 1.0   // smoothstep over one screen pixel (else a plain alpha test)
#define DECAL_STYLE_OUTLINE 2.0  // a dark band just inside the edge
#define DECAL_STYLE_GLOW 4.0     // a soft falloff across the whole spread outside the edge
#define DECAL_STYLE_SHADOW 8.0   // a drop shadow: a second, offset look-up
#define DECAL_STYLE_MSDF 16.0    // the median of RGB instead of A
// Surfaces closer to parallel to the projection axis than this fade out (|n . axis| 0.2 .. 0.45).
#define DECAL_FADE_LOW 0.2
#define DECAL_FADE_HIGH 0.45
// A bullet hole's relief (decal_box.frag, holeSlope), in atlas texels of height: the crater drops
// 3 texels over the 3 inside the edge (walls at 45 degrees: a hole punched into plaster, its walls
// catching the sun on one side and in shade on the other); the torn rim stands 0.8 texel (a lip
// 2 texels outside the edge: its outer slope lights up on the sun's side, its inner slope, which
// runs on into the crater, on the other).
#define DECAL_HOLE_CRATER 3.0
#define DECAL_HOLE_RIM 0.8
#define DECAL_MAX_CAP 1024

#endif
