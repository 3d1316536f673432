// Shared by C++ (engine_ext/lightbake) and GLSL (shaders/level/level.frag, the smoke's march):
// plain #defines only. The baked light's units are the frame's: linear irradiance, where Quake's
// light value 200 is 1.0 (map/quake_light.h: kQuakeLightUnit).
#ifndef OBSCURA_LIGHTBAKE_SHARED_H
#define OBSCURA_LIGHTBAKE_SHARED_H

// Texels of border around each face's chart in the lightmap atlas: bilinear filtering at a face's
// edge reads only its own chart (the border texels hold the edge's light, sampled inside the face).
#define LIGHTBAKE_CHART_BORDER 1

// The irradiance volume's two layers in its 3D texture (z = layer * depth + slice): the light a
// surface facing up receives (layer 0), and one facing down (layer 1). A point's ambient for a
// normal n is mix(down, up, 0.5 + 0.5 n.y): the hemisphere the frame used before the bake, made local.
#define LIGHTBAKE_PROBE_LAYERS 2

#endif
