// The level's static light, baked with Embree on the CPU (plain C++, no OGRE): what Quake's own
// `light` tool computes, in the frame's units (linear irradiance; Quake's value 200 is 1.0).
//
//   lightmaps (lightmap_atlas.h), per texel of every baked face:
//     direct    the map's light entities with their shadows (Quake's falloff formulas and keys,
//               map/quake_light.h), and the sun's visibility (1 where the sun's ray escapes or
//               reaches a sky face, else 0; the frame multiplies its shadow map by it);
//     indirect  the sky dome where the texel sees sky (a ray that escapes the level or reaches a sky
//               face), plus two diffuse bounces of the direct light off the level's faces, at
//               least the `_minlight` floor.
//   an irradiance volume (probe_grid.h) of the same indirect light at points in the air, for what
//   has no lightmap: props, the player's view model, movers and the smoke.
//
// Deterministic: every texel and probe draws its rays from an Rng seeded by its own index, so the
// result does not depend on the number of threads. The cache (bake_cache.h) keeps it on disk.
#pragma once

#include "lightbake/lightmap_atlas.h"
#include "lightbake/probe_grid.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace obscura::lightbake {

// The level-wide light the bake needs, in the frame's units (render/level_lighting.cpp fills it from
// the worldspawn keys).
struct BakeSky {
    Vec3 sunDirection{0, 1, 0};  // unit, towards the sun
    Vec3 sunColour;              // irradiance of a face square to the sun; 0 = no sun
    Vec3 above, below;           // irradiance of a face turned up (down) under a fully open sky dome
    Vec3 floor;                  // `_minlight`: the least indirect light anywhere
};

// The level's sky as the frame sees it (render/level_light_params.h: the same keys, one reading).
BakeSky bakeSkyOf(const map::Level& level);

struct BakeSettings {
    // 0.25 m: a lamp behind a 0.25 m wall still has one dark texel centre inside the wall, so the
    // bilinear filter cannot carry its light through (Quake's own luxel is 16 units, 0.5 m).
    double texel = 0.25;
    // Cosine-weighted rays a texel gathers the sky and the first bounce with (a 4 x 4 stratified
    // grid, then the 5 x 5 filter): the indirect light is smooth, and the bake's error at 16 is
    // below half the tone map's 8-bit step on a mid-grey wall (tests/lightbake: against 400 rays);
    // 36 took e3m4's cold bake from 9.4 s to 12.6 s on 2 cores.
    int gatherRays = 16;
    // Rays for the second bounce (2 x 2, filtered the same): smoother still, and a tenth of the first.
    int secondBounceRays = 4;
    int probeRays = 16;        // a probe's rays per hemisphere (4 x 4): the smoke blurs it anyway
    double probeCell = 1.0;    // metres between probes, before kMaxProbes coarsens it
    // The share of light a face sends on (Quake's textures average about 0.3 in linear terms; a
    // constant because the bake runs without the textures).
    double albedo = 0.3;
    int threads = 0;           // 0: every hardware thread
};

struct BakeStats {
    std::size_t charts = 0, texels = 0, buried = 0, probes = 0, lights = 0;
    std::uint64_t rays = 0;
    double seconds = 0;
    double directSeconds = 0, bounceSeconds = 0, probeSeconds = 0;  // the passes' shares (charting and the scene in direct's)
};

struct LightBake {
    Atlas atlas;
    std::vector<float> direct;    // RGBA a texel: the lights' irradiance with their shadows; a = sun visibility
    std::vector<float> indirect;  // RGB a texel: sky, bounce and floor
    ProbeGrid probes;
    BakeStats stats;
};

// `progress` (may be empty) gets a line now and then during a bake that takes more than a second.
LightBake bakeLevel(const map::Level& level, const BakeSky& sky, const BakeSettings& settings,
                    const std::function<void(const std::string&)>& progress = {});

// The chart of the baked face through p (within 1 um of its plane) with normal n (within 2.6
// degrees), or -1 when none: where tests and tools read the lightmap at a point.
long chartAt(const LightBake& bake, const map::Level& level, const Vec3& p, const Vec3& n);

// The baked direct light (rgb) and sun visibility (a) at a point of a baked face, bilinear as the
// GPU reads it (tests and the reference compare with this).
void sampleLightmap(const LightBake& bake, std::size_t chart, const Vec3& p, float direct[4], float indirect[3]);

}  // namespace obscura::lightbake
