// Limits the smoke's C++ glue (engine_ext/smoke/smoke_render.cpp) and its GLSL (shaders/smoke)
// share: plain #defines valid in both.
#ifndef OBSCURA_SMOKE_SHARED_H
#define OBSCURA_SMOKE_SHARED_H

// Volumes marched in one frame: the march's smokeMap0..3 samplers (samplers cannot be indexed by
// a loop variable in GLSL 3.30). With more clouds alive, the 4 oldest are marched.
#define SMOKE_MAX_VOLUMES 4

// Point lights (the level's map lights) that light the smoke in one frame: those whose range
// reaches a marched volume's box, brightest there first. 8: every light costs each march step a
// few dozen flops on every pixel the smoke covers (llvmpipe's cost is that arithmetic), and 8 is
// also what a level surface's batch gets (shaders/level/level.frag).
#define SMOKE_MAX_LIGHTS 8

#endif
