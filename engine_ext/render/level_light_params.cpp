// See level_light_params.h.
#include "render/level_light_params.h"

#include "map/quake_light.h"

namespace obscura::render {

namespace {
// Quake light values, `_sunlight` included, share one scale (map/quake_light.h): 200 maps to a sun
// of colour 1.0, which with the tone map gives a bright but unclipped wall.
constexpr double kSunlightUnit = map::kQuakeLightUnit;
// `_sunlight2` (the sky dome) of 150 gives an ambient of about 0.4 from above.
constexpr double kSkyDomeUnit = 375.0;
// The ambient of a level that places lights but sets no `_minlight`: Quake's is 0; this floor (two
// light units) keeps unlit corners a dark shape for the AO to work on (about 28/255 on a mid-grey
// wall after the tone map) instead of flat black.
constexpr double kLitLevelAmbient = 0.01;
}  // namespace

LevelLightingParams computeLevelLighting(const map::Level& level) {
    LevelLightingParams p;
    const map::LevelLightingKeys& k = level.lighting;
    if (k.sunlight > 0) {
        p.sunDirection = normalize(-k.sunTravel);
        p.sunColour = k.sunColour * (k.sunlight / kSunlightUnit);
    }
    const Vec3 dome = k.domeColour * (k.dome / kSkyDomeUnit), domeBelow = k.domeBelowColour * (k.domeBelow / kSkyDomeUnit);
    if (k.hasAmbient) {
        // Obscura's own hemisphere keys: the ambient as given (the arena keeps its look through them).
        p.skyAmbient = k.ambientSky;
        p.groundAmbient = k.ambientGround;
        p.dome = k.ambientSky;  // the ground's share is the bounce's: baked, not given
    } else if (k.hasMinlight || k.hasLightEntities) {
        // Quake's ambient: `_minlight` (else the dark floor) from everywhere, plus the sky domes.
        const Vec3 floor = k.hasMinlight ? k.minlightColour * (k.minlight / map::kQuakeLightUnit)
                                         : Vec3{kLitLevelAmbient, kLitLevelAmbient, kLitLevelAmbient};
        p.skyAmbient = floor + dome;
        p.groundAmbient = floor + domeBelow;
        p.dome = dome;
        p.domeBelow = domeBelow;
        // The dark floor stood in for the bounce; only `_minlight` itself stays a floor in the bake.
        if (k.hasMinlight) p.minlight = floor;
    } else if (k.dome > 0) {
        // A level without lights or ambient keys keeps the default hemisphere, half of it under a dome.
        p.skyAmbient = dome + p.skyAmbient * 0.5;
        p.groundAmbient = p.groundAmbient + domeBelow;
        p.dome = p.skyAmbient;
        p.domeBelow = domeBelow;
    } else {
        p.dome = p.skyAmbient;  // the default hemisphere's ground is the bounce's share: baked
    }
    return p;
}

}  // namespace obscura::render
