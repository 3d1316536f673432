// The light of the back-lit signs (engine_ext/signs), mirroring engine_ext/signs/sign_light.cpp
// line for line (throughSign, signIrradiance): the segment from a point to the sign's lamp meets the
// plate's plane at one point; the letters' distance field (metres, > 0 inside a letter) and the
// bullet holes there, against the lamp's disc seen through the plane (radius R b / (a + b)), give the
// share of the lamp that passes (the disc-segment area: exact for a straight edge). A shadow map from
// the lamp through the plate (signShadow0/1: distance to the lamp of the first surface) adds every
// other occluder. Shared by the volumetric pass (the shafts) and the signs' surface pass (the
// lettered light on floors and walls). Needs signs_shared.h.
uniform float signCount;                        // signs bound (0..SIGN_MAX_LIGHTS)
uniform vec3 signCentre[SIGN_MAX_LIGHTS];       // the plate's centre, world
uniform vec3 signRight[SIGN_MAX_LIGHTS];        // the plate's axes (orthonormal, world)
uniform vec3 signUp[SIGN_MAX_LIGHTS];
uniform vec3 signFacing[SIGN_MAX_LIGHTS];       // towards the room: the light travels along it
uniform vec4 signPlate[SIGN_MAX_LIGHTS];        // half width, half height (m), holes in use, the mask's texel (m)
uniform vec2 signMaskSize[SIGN_MAX_LIGHTS];     // the mask's texels across and down (no textureSize a sample)
uniform vec4 signLamp[SIGN_MAX_LIGHTS];         // the lamp's centre (world), w = its radius (m)
uniform vec4 signColour[SIGN_MAX_LIGHTS];       // linear colour x intensity, w = range (m)
uniform vec4 signCone[SIGN_MAX_LIGHTS];         // cos(cone), cos(0.85 cone)
uniform vec4 signHoles[SIGN_HOLE_SLOTS];        // per sign: x, y (plate, m), radius
uniform mat4 signShadowMatrix[SIGN_MAX_LIGHTS]; // world -> the shadow map's clip space
uniform sampler2D signMask0;                    // PF_FLOAT32_R: the letters' distance (m)
uniform sampler2D signMask1;
uniform sampler2D signShadow0;                  // PF_FLOAT32_R: distance from the lamp (m), 0 = none
uniform sampler2D signShadow1;
const float kSignShadowBias = 0.05;             // metres: a shadow-map texel's depth slope at grazing
                                                // angles on the receivers a room's sign lights (512 px)

const float kSignPi = 3.14159265358979;

// The mask's bilinear value at plate point xy (metres) and its patch's gradient (per metre), from
// the one 2x2 neighbourhood of texels: sign_light.cpp's SignMask::at with its gradient.
vec3 signMaskAt(int i, vec2 xy)
{
    ivec2 size = ivec2(signMaskSize[i]);
    float texel = signPlate[i].w;
    vec2 raw = vec2((xy.x + signPlate[i].x) / texel - 0.5, (signPlate[i].y - xy.y) / texel - 0.5);
    vec2 uv = clamp(raw, vec2(0.0), vec2(size - 1));
    ivec2 c0 = min(ivec2(uv), size - 1), c1 = min(c0 + 1, size - 1);
    vec2 f = uv - vec2(c0);
    float t00, t10, t01, t11;
    if (i == 0) {
        t00 = texelFetch(signMask0, c0, 0).r, t10 = texelFetch(signMask0, ivec2(c1.x, c0.y), 0).r;
        t01 = texelFetch(signMask0, ivec2(c0.x, c1.y), 0).r, t11 = texelFetch(signMask0, c1, 0).r;
    } else {
        t00 = texelFetch(signMask1, c0, 0).r, t10 = texelFetch(signMask1, ivec2(c1.x, c0.y), 0).r;
        t01 = texelFetch(signMask1, ivec2(c0.x, c1.y), 0).r, t11 = texelFetch(signMask1, c1, 0).r;
    }
    float d = mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
    float gx = raw.x == uv.x ? mix(t10 - t00, t11 - t01, f.y) / texel : 0.0;
    float gy = raw.y == uv.y ? -mix(t01 - t00, t11 - t10, f.x) / texel : 0.0;
    return vec3(d, gx, gy);
}

// Of the lamp's distance as the shadow map saw it, past the surface at p: 1 lit, 0 shadowed.
float signShadowAt(int i, vec3 p, float toLamp)
{
    vec4 clip = signShadowMatrix[i] * vec4(p, 1.0);
    if (clip.w <= 0.0) return 1.0;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
    ivec2 texel = min(ivec2(uv * float(SIGN_SHADOW_SIZE)), ivec2(SIGN_SHADOW_SIZE - 1));
    float stored = i == 0 ? texelFetch(signShadow0, texel, 0).r : texelFetch(signShadow1, texel, 0).r;
    return stored <= 0.0 || toLamp <= stored + kSignShadowBias ? 1.0 : 0.0;
}

float signDiscEdgeFraction(float d, float r)
{
    float x = clamp(d / r, -1.0, 1.0);
    return 0.5 + (x * sqrt(1.0 - x * x) + asin(x)) / kSignPi;
}

// sign_light.cpp's throughSign: the share of sign i's lamp p sees through the plate; the lamp's
// disc widened across the deciding edge by the tilt (penumbraAcrossEdge).
float signThrough(int i, vec3 p)
{
    vec3 lamp = signLamp[i].xyz;
    float b = dot(p - signCentre[i], signFacing[i]);
    float a = dot(signCentre[i] - lamp, signFacing[i]);
    if (b <= 0.0 || a <= 0.0) return 0.0;
    vec3 q = p + (lamp - p) * (b / (a + b));
    vec2 xy = vec2(dot(q - signCentre[i], signRight[i]), dot(q - signCentre[i], signUp[i]));
    vec3 toLamp = normalize(lamp - p);
    float cosPsi = abs(dot(toLamp, signFacing[i]));
    float r = max(signLamp[i].w * b / (a + b), 1e-6);
    // Outside the plate by more than the widest the lamp's image can be: the opaque edge alone hides
    // all of it (the open distance is at most the edge's), so the mask is not read (most of a frame).
    if (min(signPlate[i].x - abs(xy.x), signPlate[i].y - abs(xy.y)) * cosPsi <= -r) return 0.0;
    // The open distance and the gradient of the term that decides it (mask, a hole, the edge).
    vec3 dg = signMaskAt(i, xy);
    int holes = int(signPlate[i].z);
    for (int h = 0; h < SIGN_MAX_HOLES; ++h) {
        if (h >= holes) break;
        vec4 hole = signHoles[i * SIGN_MAX_HOLES + h];
        float r = length(xy - hole.xy), inside = hole.z - r;
        if (inside > dg.x) dg = vec3(inside, r > 0.0 ? -(xy - hole.xy) / r : vec2(0.0));
    }
    if (signPlate[i].x - abs(xy.x) < dg.x) dg = vec3(signPlate[i].x - abs(xy.x), xy.x > 0.0 ? -1.0 : 1.0, 0.0);
    if (signPlate[i].y - abs(xy.y) < dg.x) dg = vec3(signPlate[i].y - abs(xy.y), 0.0, xy.y > 0.0 ? -1.0 : 1.0);
    float d = dg.x;
    float inCone = smoothstep(signCone[i].x, signCone[i].y, -dot(toLamp, signFacing[i]));
    // Beyond the widest the ellipse can be, all of the lamp or none.
    if (abs(d) * cosPsi >= r) return (d > 0.0 ? 1.0 : 0.0) * inCone;
    vec2 g = dg.yz;
    vec2 tilt = vec2(dot(toLamp, signRight[i]), dot(toLamp, signUp[i]));
    if (length(tilt) > 1e-6 && length(g) > 1e-9 && cosPsi > 1e-6) {
        float c = dot(g, tilt) / (length(g) * length(tilt));
        r *= sqrt(c * c / (cosPsi * cosPsi) + (1.0 - c * c));
    }
    return signDiscEdgeFraction(d, r) * inCone;
}

// sign_light.cpp's signIrradiance, times the shadow map: the irradiance sign i's lamp gives p on a
// surface facing it; `toLampDir` returns the unit direction from p to the lamp.
vec3 signIrradiance(int i, vec3 p, out vec3 toLampDir)
{
    vec3 toLamp = signLamp[i].xyz - p;
    float d = length(toLamp);
    toLampDir = toLamp / max(d, 1e-6);
    float f = d / signColour[i].w;
    float w = clamp(1.0 - f * f * f * f, 0.0, 1.0);
    if (w <= 0.0) return vec3(0.0);
    float through = signThrough(i, p);
    if (through <= 0.0) return vec3(0.0);
    float r = max(d, signLamp[i].w);
    return signColour[i].rgb * (through * w * w / (r * r) * signShadowAt(i, p, d));
}
