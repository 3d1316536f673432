// Limits the signs' C++ (engine_ext/signs) and GLSL (shaders/signs) share: plain #defines valid in both.
#ifndef OBSCURA_SIGNS_SHARED_H
#define OBSCURA_SIGNS_SHARED_H

// Back-lit signs lit in one frame: the nearest to the camera. Each costs every marched sample one
// segment/plane intersection and one mask read, and every lit pixel the same; 2 keeps the
// volumetric pass's cost within the 1.3x of smoke alone on llvmpipe.
#define SIGN_MAX_LIGHTS 2

// Bullet holes a sign's mask keeps (the oldest closes when a new one is shot): each is one disc
// tested analytically per mask read (shaders/signs/sign_light.glsl), so the count bounds that cost.
#define SIGN_MAX_HOLES 16
// SIGN_MAX_LIGHTS x SIGN_MAX_HOLES, written out: OGRE's GLSL uniform parser reads an array's size as
// one number or macro, not an expression (sign_render.cpp checks the product).
#define SIGN_HOLE_SLOTS 32

// A lit sign's shadow map, texels a side (engine_ext/signs/sign_render.cpp says why 512); the
// shader reads it with texelFetch (the same texel as nearest filtering, cheaper on llvmpipe).
#define SIGN_SHADOW_SIZE 512

#endif
