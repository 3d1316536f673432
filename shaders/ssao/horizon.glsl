// Horizon-based AO (after Bavoil & Sainz, "Screen-space ambient occlusion", ShaderX7 / NVIDIA
// HBAO 2008): march a few screen-space directions (rotated per pixel) out to the projected radius;
// along each, the highest horizon above the tangent plane (the largest sine of elevation of
// H = sample - point against the normal) occludes, faded with distance. Finds large occluders that
// point samples skip, at the same sample count. Used by the horizon, heightfield and combined modes.
// Needs ssao_common.glsl.
const int kHorizonDirections = 4;  // x steps = the sample count (16 -> 4 steps a direction)

// Occlusion (0 = open, 1 = closed) of view-space point p with normal n by what lies between
// `inner` and `outer` metres from it (the combined mode's large-scale fallback counts only what the
// small scale, 0..radius, does not), faded to nothing at `outer`.
float horizonOcclusionBetween(vec4 p, vec3 n, vec3 rnd, float inner, float outer)
{
    // The range projected to texture space at this depth.
    vec2 innerUv = 0.5 * projScale * inner / -p.z;
    vec2 outerUv = 0.5 * projScale * outer / -p.z;
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
            vec2 uv = vUv + dir * (innerUv + (outerUv - innerUv) * ((float(s) + jitter) / float(steps)));
            if (!onScreen(uv)) break;
            vec4 q = viewPosition(uv);
            if (q.w < 0.5) continue;
            vec3 h = q.xyz - p.xyz;
            float dist = length(h);
            if (dist < max(inner, 1e-4)) continue;
            // sin(elevation) above the tangent plane, less a small bias against flat-surface noise
            float elevation = dot(h / dist, n) - 0.1;
            // Faded over the range: 1 at `inner`, 0 at `outer` (for the small scale, inner = 0:
            // 1 - dist^2 / radius^2, HBAO's own, the same operations as before the range).
            float near = dist - inner, span = outer - inner;
            float falloff = clamp(1.0 - (near * near) / (span * span), 0.0, 1.0);
            best = max(best, elevation * falloff);
        }
        occ += best;
    }
    return intensity * occ / float(kHorizonDirections);
}

// The small scale: everything within the radius.
float horizonOcclusion(vec4 p, vec3 n, vec3 rnd) { return horizonOcclusionBetween(p, n, rnd, 0.0, radius); }
