// Shared by C++ (engine_ext/render) and GLSL (shaders/level/level.frag): plain #defines only.
#ifndef OBSCURA_LEVEL_SHARED_H
#define OBSCURA_LEVEL_SHARED_H

// Texels a light takes in the light texture (engine_ext/render/light_grid.h: kLightTexels).
#define LEVEL_LIGHT_TEXELS 5
// Texels a row of the light texture (render/light_grid.h: kLightGridWidth), a power of two.
#define LEVEL_LIGHT_ROW_LOG2 11
#define LEVEL_LIGHT_ROW (1 << LEVEL_LIGHT_ROW_LOG2)

// Light formulas as level.frag reads them from the attenuation's y (the `delay` key, map::LightFormula).
#define LEVEL_LIGHT_LINEAR 0
#define LEVEL_LIGHT_INVERSE 1
#define LEVEL_LIGHT_INVERSE_SQUARE 2
#define LEVEL_LIGHT_NONE 3
#define LEVEL_LIGHT_LOCAL_MINIMUM 4
#define LEVEL_LIGHT_INVERSE_SQUARE_A 5
// Added to the formula of a spotlight (its cone texels are read only then).
#define LEVEL_LIGHT_SPOT_FLAG 8
// map::kInverseLightScale and map::kMinInverseDistance (quake_light.h), for the shader.
#define LEVEL_INVERSE_SCALE 128.0
#define LEVEL_MIN_INVERSE_DISTANCE 16.0

#endif
