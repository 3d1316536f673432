#version 330 core
// The combined mode (seed c's prescription, issue 14): the small scale, everything within `radius`,
// from a screen-space mode (GTAO's horizon search, gtao_search.glsl); the large scale, what lies between `radius` and
// `largeRadius`, from rays through the level's height map (heightfield.glsl), which sees walls off
// the screen and behind the camera. The two count disjoint distance ranges and their visibilities
// multiply: V = V_small(0..r) x V_large(r..R), so an occluder both could see is counted once (as
// max() of two estimates of overlapping ranges did not: it kept the larger error of the two).
// Under a roof the map says nothing; there the large scale is the screen's visibility beyond r
// (screenVisibilityBeyond).
in vec2 vUv;
out vec4 fragColour;
#include "ssao_common.glsl"
#include "gtao.glsl"
#include "gtao_search.glsl"
#include "heightfield.glsl"
uniform float largeRadius;       // metres: the large scale's reach (ssao_knobs.h, kLargeRadius)
uniform float heightRays;        // rays per pixel through the height map
uniform float visibilityPower;   // intensity / its default (ssao_compositor.cpp), as the gtao mode's

// The small scale, as visibility (1 = open): GTAO within the radius (`screen`) and, where the height
// map knows the ground (no roof: map.x >= 0), its rays over the same 0..r, the lower of the two: the
// screen misses what lies off it or behind the foreshortened floor, the map misses what lies under
// an overhang, and an occluder both see is counted once (the heightfield mode's merge, with the
// offset roof test). The map's term took the 0.6 m table's outdoor views from 2.2-2.7x to
// 5.3-6.6x better than off (engine_ext/ssao/README.md).
float smallVisibility(float screen, vec2 map) { return map.x < 0.0 ? screen : min(screen, map.x); }

// Under a roof: the screen's visibility beyond the radius, V(0..R) / V(0..r) (screen.y / screen.x,
// one march a side for both), the share of what is open to r that stays open to R. Horizons do not
// add up over ranges (a ceiling seen within r and beyond it is one horizon, the higher one), so the
// product with a horizon over r..R alone darkened a wall-ceiling crease twice (0.17 against the 2 m
// truth's 0.5 on tests/ssao's room).
float screenVisibilityBeyond(vec2 screen, float small) { return clamp(screen.y / max(small, 1e-3), 0.0, 1.0); }

void main()
{
    vec4 p = viewPosition(vUv);
    if (p.w < 0.5) { fragColour = kSkyAo; return; }
    vec3 n = viewNormal(vUv);
    vec3 rnd = pixelNoise();
    vec3 wp = (inverseView * vec4(p.xyz, 1.0)).xyz;
    vec3 wn = normalize(mat3(inverseView) * n);
    // The map's rays over 0..r and r..R in one march.
    vec2 map = heightVisibility(wp, wn, radius, largeRadius, int(heightRays));
    // The screen's far reach only where the map has no answer for the large scale.
    bool screenLarge = largeRadius > radius && map.y < 0.0;
    vec2 screen = gtaoVisibilities(p, n, rnd, radius, screenLarge ? largeRadius : radius);
    float small = clamp(smallVisibility(screen.x, map), 0.0, 1.0);
    float large = 1.0;
    if (largeRadius > radius) large = screenLarge ? screenVisibilityBeyond(screen, small) : map.y;
    float v = clamp(small * large, 1e-4, 1.0);  // pow(0, 0) is undefined (intensity 0)
    fragColour = aoResult(pow(v, visibilityPower), -p.z);
}
