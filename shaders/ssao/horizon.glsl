// Horizon-based AO (after Bavoil & Sainz, "Screen-space ambient occlusion", ShaderX7 / NVIDIA
// HBAO 2008): march a few screen-space directions (rotated per pixel) out to the projected radius;
// along each, the highest horizon above the tangent plane (the largest sine of elevation of
// H = sample - point against the normal) occludes, faded with distance. Finds large occluders that
// point samples skip, at the same sample count. Used by the horizon, heightfield and combined modes.
// Needs ssao_common.glsl.
const int kHorizonDirections = 4;  // x steps = the sample count (16 -> 4 steps a direction)

// Occlusion (0 = open, 1 = closed) of view-space point p with normal n by what lies within `reach`
// metres of it (the radius for the small scale; combined.frag also asks for its large radius).
float horizonOcclusionWithin(vec4 p, vec3 n, vec3 rnd, float reach)
{
    // The reach projected to texture space at this depth.
    vec2 reachUv = 0.5 * projScale * reach / -p.z;
    int steps = max(int(sampleCount) / kHorizonDirections, 1);
    // The per-pixel random vector's xy is the first direction; the others are it turned by 90
    // degrees each (no trigonometry per pixel).
    vec2 dir = normalize(rnd.xy + vec2(1e-4, 0.0));
    float jitter = rnd.z * 0.5 + 0.5;
    float occ = 0.0;
    for (int d = 0; d < kHorizonDirections; ++d) {
        dir = vec2(-dir.y, dir.x);
        float best = 0.0;
        for (int s = 0; s < 8; ++s) {
            if (s >= steps) break;
            vec2 uv = vUv + dir * reachUv * ((float(s) + jitter) / float(steps));
            if (!onScreen(uv)) break;
            vec4 o = offsetTo(uv, p);
            if (o.w <= 0.0) continue;
            // sin(elevation) above the tangent plane, less a small bias against flat-surface noise
            float elevation = dot(o.xyz, n) - 0.1;
            float falloff = clamp(1.0 - (o.w * o.w) / (reach * reach), 0.0, 1.0);
            best = max(best, elevation * falloff);
        }
        occ += best;
    }
    return intensity * occ / float(kHorizonDirections);
}

// The small scale: everything within the radius.
float horizonOcclusion(vec4 p, vec3 n, vec3 rnd) { return horizonOcclusionWithin(p, n, rnd, radius); }
