#version 330 core
// The combined mode (seed c's prescription, issue 14): the small scale, everything within `radius`,
// from a screen-space mode (horizon.glsl); the large scale, what lies between `radius` and
// `largeRadius`, from rays through the level's height map (heightfield.glsl), which sees walls off
// the screen and behind the camera. The two count disjoint distance ranges and their visibilities
// multiply: V = V_small(0..r) x V_large(r..R), so an occluder both could see is counted once (as
// max() of two estimates of overlapping ranges did not: it kept the larger error of the two).
// Under a roof the map says nothing; there the large scale is the screen's horizon over r..R.
in vec2 vUv;
out vec4 fragColour;
#include "ssao_common.glsl"
#include "horizon.glsl"
#include "heightfield.glsl"
uniform float largeRadius;       // metres: the large scale's reach (ssao_knobs.h, kLargeRadius)
uniform float heightRays;        // rays per pixel through the height map

// The small scale: the one screen-space mode this mode is built on.
float smallOcclusion(vec4 p, vec3 n, vec3 rnd) { return horizonOcclusion(p, n, rnd); }

void main()
{
    vec4 p = viewPosition(vUv);
    if (p.w < 0.5) { fragColour = kSkyAo; return; }
    vec3 n = viewNormal(vUv);
    vec3 rnd = pixelNoise();
    float small = 1.0 - clamp(smallOcclusion(p, n, rnd), 0.0, 1.0);
    float large = 1.0;
    if (largeRadius > radius) {
        vec3 wp = (inverseView * vec4(p.xyz, 1.0)).xyz;
        vec3 wn = normalize(mat3(inverseView) * n);
        large = heightVisibility(wp, wn, radius, largeRadius, int(heightRays));
        if (large < 0.0) large = 1.0 - clamp(horizonOcclusionBetween(p, n, rnd, radius, largeRadius), 0.0, 1.0);
    }
    fragColour = aoResult(small * large, -p.z);
}
