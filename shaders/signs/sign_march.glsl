// The back-lit signs' shafts in the frame's volumetric pass (shaders/frame/volumes.frag): where a
// view ray crosses a sign's beam (signSegments) and the light scattered towards the eye there per
// unit of scattering coefficient (signScatterAt), from the same light the surfaces get
// (sign_light.glsl). The medium is the smoke plus a thin haze (signHaze, per metre, a knob): the haze
// only scatters (optically thin: its extinction over a room, a few per cent, is neglected, and the
// reference, tools/signref, neglects it too).
#include "signs_shared.h"
#include "sign_light.glsl"
#include "volume_phase.glsl"
uniform float signHaze;         // haze scattering coefficient, per metre (SignSettings::haze)
const float kSignG = 0.3;       // Henyey-Greenstein asymmetry of the haze: as the smoke's, forward
                                // enough to glow towards the lamp, wide enough to show from the side

// Clips [t0, t1] of origin + t dir to the half-space dot(n, x) <= d.
void signClip(vec3 origin, vec3 dir, vec3 n, float d, inout float t0, inout float t1)
{
    float dn = dot(n, dir), dist = d - dot(n, origin);
    if (abs(dn) < 1e-7) {
        if (dist < 0.0) t1 = -1.0;
        return;
    }
    float t = dist / dn;
    if (dn > 0.0) t1 = min(t1, t);
    else t0 = max(t0, t);
}

// Each sign's beam: the pyramid from its lamp through the plate's rectangle, in front of the plate
// and within its range: an interval of the ray, added to the pass's list.
void signSegments(vec3 origin, vec3 dir, float maxT, inout int n, inout float segT0[VOLUME_MAX_SEGMENTS],
                  inout float segT1[VOLUME_MAX_SEGMENTS])
{
    int count = int(signCount);
    for (int i = 0; i < SIGN_MAX_LIGHTS; ++i) {
        if (i >= count) break;
        vec3 c = signCentre[i], lamp = signLamp[i].xyz, f = signFacing[i];
        vec3 r = signRight[i] * signPlate[i].x, u = signUp[i] * signPlate[i].y;
        float t0 = 0.0, t1 = maxT;
        signClip(origin, dir, -f, -dot(f, c), t0, t1);                  // in front of the plate
        signClip(origin, dir, f, dot(f, lamp) + signColour[i].w, t0, t1);  // within the range
        // The four sides: planes through the lamp and each edge of the plate, normals outwards.
        vec3 corners[4] = vec3[4](c - r - u, c + r - u, c + r + u, c - r + u);
        for (int e = 0; e < 4; ++e) {
            vec3 side = normalize(cross(corners[(e + 1) % 4] - lamp, corners[e] - lamp));
            if (dot(side, c - lamp) > 0.0) side = -side;
            signClip(origin, dir, side, dot(side, lamp), t0, t1);
        }
        if (t1 <= t0) continue;
        segT0[n] = t0;
        segT1[n] = t1;
        ++n;
    }
}

// The signs' light at p scattered along -dir (towards the eye), per unit scattering coefficient;
// shadow[i]: what reaches p of sign i's lamp past the smoke (volumes.frag, from the smoke's lamp maps).
vec3 signScatterAt(vec3 p, vec3 dir, float shadow[SIGN_MAX_LIGHTS])
{
    vec3 light = vec3(0.0);
    int count = int(signCount);
    for (int i = 0; i < SIGN_MAX_LIGHTS; ++i) {
        if (i >= count) break;
        vec3 toLamp;
        vec3 e = signIrradiance(i, p, toLamp);
        // The light travels along -toLamp; the eye looks along dir.
        light += shadow[i] * e * volumePhase(dot(dir, -toLamp), kSignG);
    }
    return light;
}
