#version 330 core
// Heightfield AO (seed c, directtovideo / Frameranger "SSAO is crease darkening"): screen-space AO
// cannot see a wall just off-screen or behind the camera. The level's top-down height map (the
// highest solid surface over each spot, rendered once per level by OGRE, sky brushes left out) can:
// rays from the surface point, cosine-weighted about its normal, are marched through it and a ray
// is blocked where it passes under the height map. Points under a roof (the height map above them)
// learn nothing from it and keep the small-scale term alone. Combined with the horizon mode by
// taking the larger occlusion, so a crease both see is not darkened twice. Kept beside the combined
// mode, which fixes its faults, for comparison (engine_ext/ssao/README.md).
in vec2 vUv;
out vec4 fragColour;
#include "ssao_common.glsl"
#include "horizon.glsl"
#include "heightfield.glsl"
uniform float heightRays;        // rays per pixel (the first entries of the hemisphere kernel)
const int kHeightSteps = 8;      // steps a ray: the seed's ~8; more did not change the error table
// metres: a height-map texel over the point this much higher is a roof. Tested at the point itself,
// so a wall's face reads its own top as a roof (no large scale there) and a thin ceiling slab's
// crease gets a black band: the combined mode (combined.frag) tests off the surface instead.
const float kPointRoofMargin = 0.3;

void main()
{
    vec4 p = viewPosition(vUv);
    if (p.w < 0.5) { fragColour = kSkyAo; return; }
    vec3 n = viewNormal(vUv);
    vec3 rnd = pixelNoise();
    float occ = horizonOcclusion(p, n, rnd);

    vec3 wp = (inverseView * vec4(p.xyz, 1.0)).xyz;
    vec3 wn = normalize(mat3(inverseView) * n);
    if (heightAt(wp) < wp.y + kPointRoofMargin) {
        // Open sky above: march the rays. Start a little off the surface so it does not block itself.
        vec3 wr = normalize(mat3(inverseView) * rnd);
        vec3 t = normalize(wr - wn * dot(wr, wn));
        mat3 tbn = mat3(t, cross(wn, t), wn);
        float jitter = rnd.z * 0.5 + 0.5;
        float open = 0.0, total = 0.0;
        int rays = int(heightRays);
        for (int i = 0; i < SSAO_MAX_SAMPLES; ++i) {
            if (i >= rays) break;
            vec3 dir = normalize(kernel[i]);
            float w = dir.z;  // cosine weight: the hemisphere kernel is uniform over directions
            dir = tbn * dir;
            float blocked = 0.0;
            for (int s = 0; s < kHeightSteps; ++s) {
                vec3 q = wp + wn * 0.05 + dir * (radius * (float(s) + jitter) / float(kHeightSteps));
                if (heightAt(q) > q.y) { blocked = 1.0; break; }
            }
            open += w * (1.0 - blocked);
            total += w;
        }
        float heightOcc = 1.0 - open / max(total, 1e-4);
        occ = max(occ, heightOcc);
    }
    fragColour = aoResult(1.0 - occ, -p.z);
}
