// The baked irradiance volume (engine_ext/lightbake/probe_grid.h) for surfaces without lightmap
// charts (props, models, movers, sign plates): the indirect light a surface with normal n at p
// receives, trilinear between probes, mix(down, up, 0.5 + 0.5 n.y). Without a bake bound
// (lightProbeSize.w = 0) the level's hemisphere from ObscuraLighting, as before the bake.
#include "lightbake_shared.h"
uniform sampler3D lightProbes;  // RGBA16F, nx x ny x (LIGHTBAKE_PROBE_LAYERS nz): the up layer, then the down layer
uniform vec4 lightProbeOrigin;  // xyz: the first probe (metres, world); w: metres between probes
uniform vec4 lightProbeSize;    // probes along x, y, z; w: 1 when a bake is bound
uniform vec3 skyAmbient;        // ObscuraLighting: the hemisphere without a bake
uniform vec3 groundAmbient;

vec3 probeAmbient(vec3 p, vec3 n)
{
    float skyward = 0.5 + 0.5 * n.y;
    if (lightProbeSize.w < 0.5) return mix(groundAmbient, skyAmbient, skyward);
    vec3 size = lightProbeSize.xyz;
    // Probe i sits at texel centre i + 0.5; clamped so a layer never filters into the other.
    vec3 g = clamp((p - lightProbeOrigin.xyz) / lightProbeOrigin.w + 0.5, vec3(0.5), size - 0.5);
    float depth = float(LIGHTBAKE_PROBE_LAYERS) * size.z;
    vec3 up = texture(lightProbes, vec3(g.xy / size.xy, g.z / depth)).rgb;
    vec3 down = texture(lightProbes, vec3(g.xy / size.xy, (g.z + size.z) / depth)).rgb;
    return mix(down, up, skyward);
}
