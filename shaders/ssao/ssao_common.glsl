// Shared by the AO modes: G-buffer access and projection between view space and texture space.
#include "ssao_shared.h"
uniform sampler2D gbufferDepth;   // linear depth, metres; 0 where nothing was drawn (sky)
uniform sampler2D gbufferNormal;  // view-space normal packed to 0..1
uniform sampler2D noiseMap;       // 4x4 random unit vectors (packed to 0..1)
uniform vec2 projScale;           // projection matrix [0][0] and [1][1]
uniform float flipY;              // 1 when render textures are stored upside down
uniform float radius;             // metres
uniform float intensity;
uniform vec3 kernel[SSAO_MAX_SAMPLES];
uniform float sampleCount;

vec2 projectToUv(vec3 p)
{
    vec2 uv = (projScale * p.xy / -p.z) * 0.5 + 0.5;
    if (flipY > 0.5) uv.y = 1.0 - uv.y;
    return uv;
}

// Whether uv lies on the screen. Every mode tests this before it reads a sample's surface: what lies
// past the border is unknown, and a depth read clamped to the edge texel but placed at the
// unclamped uv is a surface that is not there (cone darkened the whole border that way).
bool onScreen(vec2 uv) { return all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0))); }
// The same test in texel-space coordinates (uv * size), for the marches that step in texels.
bool onScreenTexels(vec2 at, vec2 size) { return all(greaterThanEqual(at, vec2(0.0))) && all(lessThanEqual(at, size)); }

// The G-buffer texel under uv. texelFetch: a plain load, no filtering (several times cheaper than
// texture() on llvmpipe, and the depth must not be filtered anyway).
ivec2 gbufferTexel(vec2 uv)
{
    ivec2 size = textureSize(gbufferDepth, 0);
    return clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
}
float depthAt(vec2 uv)
{
    return texelFetch(gbufferDepth, gbufferTexel(uv), 0).r;
}

// View space from the depth texture's texels: the point seen at texel t at linear depth d is
// (vec2(t) * scale + bias) * d, -d) (projectToUv's inverse at the texel's centre, with the flip
// folded into the y scale). Hoisted out of the horizon searches' loops, where it replaced a divide,
// a floor and two textureSize calls per step (ssao README, "GTAO's cost").
struct TexelFrame { ivec2 size; vec2 scale; vec2 bias; };
TexelFrame texelFrame()
{
    TexelFrame f;
    f.size = textureSize(gbufferDepth, 0);
    vec2 size = vec2(f.size);
    vec2 flip = vec2(1.0, flipY > 0.5 ? -1.0 : 1.0);
    f.scale = flip * 2.0 / (size * projScale);
    f.bias = flip * (1.0 / size - 1.0) / projScale;
    return f;
}
// The view-space position of texel t's surface; w = 0 for sky (depth 0).
vec4 viewPositionAtTexel(TexelFrame f, ivec2 t)
{
    float depth = texelFetch(gbufferDepth, t, 0).r;
    return vec4((vec2(t) * f.scale + f.bias) * depth, -depth, depth > 0.0 ? 1.0 : 0.0);
}

// The view-space position seen at uv; w = 0 for sky. The position is rebuilt at the centre of the
// depth texel actually read: a half-resolution pass's pixel centre falls between full-resolution
// texels, and rebuilding there tilts sloped surfaces into bands.
vec4 viewPosition(vec2 uv) { return viewPositionAtTexel(texelFrame(), gbufferTexel(uv)); }

// The horizon searches' sample: the direction from view-space point p to the visible surface at uv
// (xyz, unit) and its distance (w); w = 0 where there is nothing (sky) or the surface is p itself,
// and the search skips the sample.
vec4 offsetTo(vec2 uv, vec4 p)
{
    vec4 q = viewPosition(uv);
    if (q.w < 0.5) return vec4(0.0);
    vec3 h = q.xyz - p.xyz;
    float dist = length(h);
    return dist < 1e-4 ? vec4(0.0) : vec4(h / dist, dist);
}

vec3 viewNormal(vec2 uv)
{
    return normalize(texelFetch(gbufferNormal, gbufferTexel(uv), 0).xyz * 2.0 - 1.0);
}

// What every AO pass writes: the AO term and this pixel's linear depth, which the blur and the
// composite's depth-aware upsampling read beside it (depth 0 = sky, never occluded).
vec4 aoResult(float ao, float depth)
{
    return vec4(clamp(ao, 0.0, 1.0), depth, 0.0, 1.0);
}
const vec4 kSkyAo = vec4(1.0, 0.0, 0.0, 1.0);

// Random rotation per pixel from a tiled 4x4 texture (interleaved sampling).
vec3 pixelNoise()
{
    return normalize(texelFetch(noiseMap, ivec2(gl_FragCoord.xy) & 3, 0).xyz * 2.0 - 1.0);
}

// 1 if the scene surface seen at q's pixel lies in front of q (q is inside geometry), weighted
// down when that surface is far outside the radius (it only hides q from view: a false occluder).
float occluderAt(vec3 q, float centreZ)
{
    vec2 uv = projectToUv(q);
    if (!onScreen(uv)) return 0.0;
    float depth = depthAt(uv);
    if (depth <= 0.0) return 0.0;  // sky
    float sz = -depth;
    float inFront = sz >= q.z + 0.02 * radius ? 1.0 : 0.0;
    float range = smoothstep(0.0, 1.0, radius / max(abs(centreZ - sz), 1e-4));
    return inFront * range;
}
