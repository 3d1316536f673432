// Shared by C++ (engine_ext/render) and GLSL (shaders/level/level.frag): plain #defines only.
#ifndef OBSCURA_LEVEL_SHARED_H
#define OBSCURA_LEVEL_SHARED_H

// Lights one level batch is lit by: the size of level.frag's light arrays and the material pass's
// `max_lights` (media/materials: level.program, level.material; a test checks they agree).
// LevelGeometry cuts chunks until no chunk is reached by more (the sun takes one), so none is dropped.
// 32: e3m4's busiest 16 m chunk is reached by 21 lights; at 32 its chunks need no cut, and a pixel
// loops only over the lights of its own chunk (an unused slot costs nothing: the loop stops at the
// count).
#define LEVEL_MAX_LIGHTS 32

// Light formulas as level.frag reads them from the attenuation's y (the `delay` key, map::LightFormula).
#define LEVEL_LIGHT_LINEAR 0
#define LEVEL_LIGHT_INVERSE 1
#define LEVEL_LIGHT_INVERSE_SQUARE 2
#define LEVEL_LIGHT_NONE 3
#define LEVEL_LIGHT_LOCAL_MINIMUM 4
#define LEVEL_LIGHT_INVERSE_SQUARE_A 5
// map::kInverseLightScale and map::kMinInverseDistance (quake_light.h), for the shader.
#define LEVEL_INVERSE_SCALE 128.0
#define LEVEL_MIN_INVERSE_DISTANCE 16.0

#endif
