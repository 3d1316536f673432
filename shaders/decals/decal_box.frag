#version 330 core
// A deferred box decal (Kim 2012, Persson 2011) with an alpha-tested distance field (Green 2007):
//  1. the G-buffer's linear depth at this pixel -> the surface's view position (along the ray
//     through the box's back face) -> world -> the decal's box; outside [-1, 1]^3: nothing;
//  2. the surface's normal against the projection axis: back-facing rejected, grazing faded;
//  3. the atlas read with explicit gradients from the depth (the pixel's footprint on the
//     surface), not from screen derivatives, which jump where a foreground object crosses the decal
//     (the fringe, Wronski 2015); the same footprint sets the antialiasing width;
//  4. the style: alpha test or smoothstep, an outline band, a glow, a drop shadow; multi-channel
//     (median of RGB) or true distance (A).
//  5. a bullet hole bends the normal: a crater sloping in from the edge and a torn rim raised
//     just outside it, a height profile of the distance field, its gradient from the field's own
//     slope (two more look-ups one footprint apart).
// Outputs (blended one / one-minus-source-alpha): premultiplied albedo (gamma) and coverage;
// premultiplied bent world normal and its coverage (0 for every decal but a hole).
#include "decals_shared.h"
uniform sampler2D gbufferDepth;
uniform sampler2D gbufferNormal;
uniform sampler2D decalAtlas;
uniform sampler2D decalData;
uniform mat4 inverseView;
uniform mat4 projection;
uniform vec4 viewportSize;  // width, height, 1/width, 1/height
uniform float atlasTiles;   // tiles side by side in decalAtlas: DECAL_TILES + the level's signs
in vec3 vViewPos;
flat in int vSlot;
layout(location = 0) out vec4 fragColour;
layout(location = 1) out vec4 fragNormal;

float median3(vec3 v) { return max(min(v.r, v.g), min(max(v.r, v.g), v.b)); }
bool has(float style, float bit) { return mod(floor(style / bit), 2.0) > 0.5; }

// The signed distance in atlas texels at `uv` (tile-local 0..1), > 0 inside.
float distanceAt(vec2 uv, float tile, bool msdf, vec2 grad)
{
    float inset = 0.5 / float(DECAL_TILE);
    vec2 atlasUv = vec2((tile + clamp(uv.x, inset, 1.0 - inset)) / atlasTiles, clamp(uv.y, inset, 1.0 - inset));
    vec4 t = textureGrad(decalAtlas, atlasUv, vec2(grad.x / atlasTiles, 0.0), vec2(0.0, grad.y));
    float v = msdf ? median3(t.rgb) : t.a;
    return (v - 0.5) * 2.0 * DECAL_RANGE;
}

// A bullet hole's surface height (in atlas texels) against the distance d (texels, > 0 inside):
// a crater falling DECAL_HOLE_CRATER texels over the first 3 inside the edge, a torn rim raised
// DECAL_HOLE_RIM texels 2 outside it (a Gaussian 0.8 texel wide: its outer slope ends before the
// field's range, 4 texels, where the gradient vanishes). Returns dh/dd.
float holeSlope(float d)
{
    float x = (d + 2.0) / 0.8;
    float rim = DECAL_HOLE_RIM * -2.0 * x * exp(-x * x) / 0.8;
    float t = clamp(d / 3.0, 0.0, 1.0);
    float crater = -DECAL_HOLE_CRATER * 6.0 * t * (1.0 - t) / 3.0;
    return rim + crater;
}

// The hole's bent world normal, premultiplied by its coverage: the field's gradient (forward
// differences one footprint apart, at least a texel: the slope seen at this pixel's size) along
// the box's axes, tilting the surface normal n by the profile's slope.
vec4 holeNormal(vec3 n, vec3 axisX, vec3 axisY, vec2 uv, float tile, bool msdf, vec2 grad, float d, float footprint)
{
    if (d < -4.0) return vec4(0.0);
    float step = max(footprint, 1.0);
    vec2 du = vec2(step / float(DECAL_TILE), 0.0);
    float gx = (distanceAt(uv + du, tile, msdf, grad) - d) / step;
    float gy = (distanceAt(uv + du.yx, tile, msdf, grad) - d) / step;
    // uv.x runs along the box's +x, uv.y against its +y (decal_box.frag: uv from box).
    vec3 along = gx * normalize(axisX) - gy * normalize(axisY);
    along -= n * dot(n, along);
    vec3 bent = normalize(n - holeSlope(d) * along);
    float cover = smoothstep(-4.0, -3.4, d);
    return vec4(bent * cover, cover);
}

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    if (depth <= 0.0) discard;  // sky
    vec3 viewPos = vViewPos * (depth / -vViewPos.z);
    vec3 world = (inverseView * vec4(viewPos, 1.0)).xyz;
    vec4 r0 = texelFetch(decalData, ivec2(0, vSlot), 0);
    vec4 r1 = texelFetch(decalData, ivec2(1, vSlot), 0);
    vec4 r2 = texelFetch(decalData, ivec2(2, vSlot), 0);
    vec4 info = texelFetch(decalData, ivec2(3, vSlot), 0);
    vec4 tint = texelFetch(decalData, ivec2(4, vSlot), 0);
    vec3 box = vec3(dot(r0.xyz, world) + r0.w, dot(r1.xyz, world) + r1.w, dot(r2.xyz, world) + r2.w);
    if (any(greaterThan(abs(box), vec3(1.0)))) discard;

    // Facing: the G-buffer's view normal to the world, against the box's +z.
    vec3 nView = texelFetch(gbufferNormal, pixel, 0).xyz * 2.0 - 1.0;
    vec3 n = normalize(mat3(inverseView) * nView);
    float facing = dot(n, normalize(r2.xyz));
    float fade = smoothstep(DECAL_FADE_LOW, DECAL_FADE_HIGH, facing) * (1.0 - smoothstep(0.6, 1.0, abs(box.z)));
    if (fade <= 0.0) discard;

    // The pixel's footprint on the surface (metres), from the depth alone: never the jump of a
    // screen-space derivative across a silhouette. In tile units per axis, and in atlas texels.
    float pixelMetres = 2.0 * depth / (abs(projection[1][1]) * viewportSize.y) / max(facing, 0.25);
    vec2 grad = pixelMetres * 0.5 * vec2(length(r0.xyz), length(r1.xyz));
    float footprint = max(grad.x, grad.y) * float(DECAL_TILE);  // atlas texels a pixel
    vec2 uv = vec2(box.x * 0.5 + 0.5, 0.5 - box.y * 0.5);

    float tile = info.x, style = info.y;
    bool msdf = has(style, DECAL_STYLE_MSDF);
    float d = distanceAt(uv, tile, msdf, grad);
    float w = max(0.5 * footprint, 0.02);  // half a pixel, in texels
    float cover = has(style, DECAL_STYLE_SMOOTH) ? smoothstep(-w, w, d) : step(0.0, d);

    vec3 colour;
    float alpha;
    fragNormal = vec4(0.0);
    if (tile == float(DECAL_TILE_BULLET)) {
        fragNormal = holeNormal(n, r0.xyz, r1.xyz, uv, tile, msdf, grad, d, footprint) * fade * info.z;
        // Torn paint at the rim, a black hole inside it (the outline band: 3 texels in).
        float core = smoothstep(3.0 - w, 3.0 + w, d);
        colour = mix(vec3(0.3, 0.28, 0.25), vec3(0.01), has(style, DECAL_STYLE_OUTLINE) ? core : 1.0);
        alpha = cover;
    } else if (tile == float(DECAL_TILE_SCORCH)) {
        // Soft across the whole spread (the glow threshold), darkest in the middle.
        colour = vec3(0.02, 0.018, 0.016);
        alpha = has(style, DECAL_STYLE_GLOW) ? smoothstep(-DECAL_RANGE, DECAL_RANGE, d) : cover;
    } else if (tile == float(DECAL_TILE_SIGN)) {
        colour = vec3(0.92, 0.9, 0.85);
        alpha = cover;
    } else {
        colour = vec3(0.8, 0.62, 0.1);  // a plate
        alpha = cover;
    }
    if (tint.w > 0.5) colour = tint.rgb;
    if (has(style, DECAL_STYLE_OUTLINE) && tile != float(DECAL_TILE_BULLET)) {
        float band = smoothstep(-w, w, d) * (1.0 - smoothstep(1.0 - w, 1.0 + w, d));
        colour = mix(colour, vec3(0.02), band);
    }
    // Glow: soot fading across the spread outside the edge (under the shape).
    vec4 result = vec4(colour * alpha, alpha);
    if (has(style, DECAL_STYLE_GLOW)) {
        float glow = 0.6 * clamp(1.0 + d / DECAL_RANGE, 0.0, 1.0);
        glow *= glow;
        result = result + vec4(vec3(0.03) * glow, glow) * (1.0 - result.a);
    }
    // Drop shadow: the same field 1.5 texels down and right, dark, under the shape.
    if (has(style, DECAL_STYLE_SHADOW)) {
        float ds = distanceAt(uv - vec2(1.5) / float(DECAL_TILE), tile, msdf, grad);
        float shadow = 0.7 * smoothstep(-1.0 - w, 1.0 + w, ds);
        result = result + vec4(0.0, 0.0, 0.0, shadow) * (1.0 - result.a);
    }
    fragColour = result * fade * info.z;
}
