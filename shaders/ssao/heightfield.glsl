// The level's top-down height map (seed c, directtovideo / Frameranger): the highest solid surface
// over each spot, rendered once per level by OGRE (ssao_compositor.cpp), sky brushes left out. A
// ray from a surface point is blocked where it passes under the map. Used by the heightfield and
// combined modes. Needs ssao_common.glsl.
uniform sampler2D heightMap;     // world Y of the highest surface, metres; very low = nothing there
uniform mat4 heightViewProj;     // world -> the height camera's clip space (x, z -> texture)
uniform mat4 inverseView;        // view -> world

float heightAt(vec3 world)
{
    vec4 clip = heightViewProj * vec4(world, 1.0);
    return texture(heightMap, clip.xy * 0.5 + 0.5).r;
}

// Metres off the surface, along its normal, where the roof test is made: 2 texels of the map
// (10 cm over the arena, 15 over e3m4), so a wall's own texel (its top, metres above a point on its
// face) is not a roof over its face.
const float kRoofTestOffset = 0.3;
// Metres the rays are lifted off the surface along its normal: a texel of the map, so a ray leaving
// a wall's face nearly along it does not start in the wall's own texel. The rays' distances are
// measured from the surface point: starting them at the roof test's offset reached 0.3 m further
// and darkened a wall's face 1.5 m from another by 0.17 against the 2 m truth.
const float kRayLift = 0.1;
// Metres: the map over the offset point this much higher is a roof (a ceiling, an overhang) over
// the point. Small: measured at the offset point, open ground and walls read at most a texel's
// quantisation above it; any more left a band along the wall-ceiling crease of a thin ceiling slab.
const float kRoofMargin = 0.05;
// Metres: below this the map holds "nothing here" (ssao_compositor.cpp's kNoHeight, -1e4).
const float kNothingBelow = -1e3;
const int kLargeSteps = 8;       // steps a ray a range: the seed's ~8 (0.075 m over 0..0.6 m, 0.2 m over 0.6..2 m)

// The rays' per-pixel turn and step offset, in [0, 1): a 5x5 interleaved pattern in which any 5
// consecutive pixels of a row or of a column hold all 5 values of each (turn = 2x + y, offset =
// x + 2y, mod 5; together all 25 pairs in a 5x5 block). The blur is 5 taps each way, and on a
// grazing wall only its vertical pass works (the depth changes too fast across the wall for the
// horizontal one): a column's 5 taps then see every turn, where the 4x4 random rotations (and
// interleaved gradient noise, tried) left each column its own average: vertical stripes.
vec2 rayPattern(vec2 pixel)
{
    ivec2 p = ivec2(pixel);
    return (vec2(float((2 * p.x + p.y) % 5), float((p.x + 2 * p.y) % 5)) + 0.5) / 5.0;
}

// Visibilities (1 = open) of world point wp with world normal wn through what the height map holds:
// x over 0..`inner` metres, y beyond it out to `outer` (the share of the rays open to `inner` that
// stay open to `outer`, so x * y is the visibility over 0..outer); (-1, -1) where the map says
// nothing: under a roof (the map over the point holds the roof's top, and says nothing about what
// lies between the roof and it), or where it holds nothing at all (no map baked, or a model's
// surface the map leaves out: Sibenik is one model, and every ray would have gone unblocked).
// `rays` rays, cosine-weighted about the normal (a Fibonacci spiral on the unit disc lifted to the
// hemisphere: each ray weighs the same), the spiral turned per pixel by rayPattern; kLargeSteps
// steps over each range. One march serves both ranges: a ray blocked within `inner` is not marched
// on (with outer <= inner, y is 1).
vec2 heightVisibility(vec3 wp, vec3 wn, float inner, float outer, int rays)
{
    vec3 o = wp + wn * kRoofTestOffset;
    float over = heightAt(o);
    if (over > o.y + kRoofMargin || over < kNothingBelow) return vec2(-1.0);
    vec3 start = wp + wn * kRayLift;
    vec3 a = abs(wn.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 t = normalize(cross(a, wn));
    vec3 b = cross(wn, t);
    vec2 pattern = rayPattern(gl_FragCoord.xy);
    float turn = 6.2831853 * pattern.x;
    float jitter = pattern.y;
    int openNear = 0, openFar = 0;
    for (int i = 0; i < 32; ++i) {
        if (i >= rays) break;
        float r = sqrt((float(i) + 0.5) / float(rays));
        float phi = turn + 2.3999632 * float(i);  // the golden angle
        vec3 dir = t * (r * cos(phi)) + b * (r * sin(phi)) + wn * sqrt(max(1.0 - r * r, 0.0));
        bool blocked = false;
        for (int s = 0; s < kLargeSteps && !blocked; ++s) {
            vec3 q = start + dir * (inner * (float(s) + jitter) / float(kLargeSteps));
            blocked = heightAt(q) > q.y;
        }
        if (blocked) continue;
        ++openNear;
        for (int s = 0; s < kLargeSteps && !blocked && outer > inner; ++s) {
            vec3 q = start + dir * mix(inner, outer, (float(s) + jitter) / float(kLargeSteps));
            blocked = heightAt(q) > q.y;
        }
        if (!blocked) ++openFar;
    }
    return vec2(float(openNear) / float(rays), openNear > 0 ? float(openFar) / float(openNear) : 1.0);
}
