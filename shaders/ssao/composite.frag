#version 330 core
// The last pass of every AO mode: upsamples the (blurred) AO to full resolution depth-aware, takes
// the occluded share of the ambient light off the lit colour (direct sun and point lights stay as
// they were), and tone-maps again. Or shows the AO alone. The colour arrives tone-mapped (8 bits,
// G-buffer 0): undoing level.frag's 1 - exp(-x) and gamma 2.2 gives the light back, the ambient
// share (G-buffer 3) scaled by the occlusion comes off it, and where AO = 1 the pixel is unchanged.
uniform sampler2D colourMap;   // lit colour as the plain view shows it (G-buffer 0)
uniform sampler2D aoMap;       // r = AO, g = depth, at the AO's resolution
uniform sampler2D ambientMap;  // the ambient share of that light per channel (G-buffer 3)
uniform sampler2D depthMap;    // linear depth at full resolution (G-buffer 1)
uniform float aoOnly;
uniform float aoPresent;       // 0 in the plain chain (AO off, smoke on): AO is 1 everywhere
uniform float depthSharpness;  // as the blur's
uniform sampler2D smokeMap;     // rgb = smoke light (HDR), a = transmittance, at half resolution
uniform float smokePresent;    // 0: no smoke volumes this frame, smokeMap is not read
in vec2 vUv;
out vec4 fragColour;
const float kSameSurface = 0.02;  // relative depth: 2 cm at 1 m, 20 cm at 10 m

// Joint bilateral upsampling (Kopf et al. 2007): the four AO texels around this pixel, with their
// bilinear weights times how close their depth is to this pixel's, so AO stops at silhouettes.
float upsampledAo(float depth)
{
    vec2 size = vec2(textureSize(aoMap, 0));
    vec2 st = vUv * size - 0.5;
    vec2 base = floor(st), f = st - base;
    float sum = 0.0, weights = 0.0;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            vec2 tap = texelFetch(aoMap, clamp(ivec2(base) + ivec2(x, y), ivec2(0), ivec2(size) - 1), 0).rg;
            float bilinear = (x == 0 ? 1.0 - f.x : f.x) * (y == 0 ? 1.0 - f.y : f.y);
            float w = bilinear * exp(-abs(tap.g - depth) / max(depth, 1e-3) * depthSharpness) + 1e-4;
            sum += tap.r * w;
            weights += w;
        }
    return sum / weights;
}

// The smoke at a silhouette: the four half-resolution texels weighted by how close the depth they
// were marched against (the full-resolution depth at their centre) is to this pixel's, so a near
// object in front of a cloud keeps a clean edge.
vec4 upsampledSmoke(float depth, vec4 blended)
{
    vec2 size = vec2(textureSize(smokeMap, 0));
    vec2 st = vUv * size - 0.5;
    vec2 base = floor(st), f = st - base;
    ivec2 full = textureSize(depthMap, 0);
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            ivec2 texel = clamp(ivec2(base) + ivec2(x, y), ivec2(0), ivec2(size) - 1);
            vec2 centre = (vec2(texel) + 0.5) / size;
            float d = texelFetch(depthMap, clamp(ivec2(centre * vec2(full)), ivec2(0), full - 1), 0).r;
            float bilinear = (x == 0 ? 1.0 - f.x : f.x) * (y == 0 ? 1.0 - f.y : f.y);
            // Sky (depth 0) counts as very far.
            float dz = abs((d > 0.0 ? d : 1e4) - (depth > 0.0 ? depth : 1e4)) / max(depth > 0.0 ? depth : 1e4, 1e-3);
            float w = bilinear * exp(-dz * depthSharpness) + 1e-4;
            sum += texelFetch(smokeMap, texel, 0) * w;
            weights += w;
        }
    return sum / weights;
}

void main()
{
    // From the quad's uv, not gl_FragCoord: the viewport may be a window while the G-buffer is a
    // render texture stored upside down, and the uv accounts for that.
    ivec2 size = textureSize(depthMap, 0);
    ivec2 pixel = clamp(ivec2(vUv * vec2(size)), ivec2(0), size - 1);
    float depth = texelFetch(depthMap, pixel, 0).r;
    float ao = 1.0;  // (also the AO-only view's value where nothing is drawn)
    if (depth > 0.0 && aoPresent > 0.5) {
        // One bilinear tap gives the AO and the depth of the four texels averaged: where that depth
        // matches this pixel's (no silhouette among them, most of the frame) it is the answer.
        vec2 blended = texture(aoMap, vUv).rg;
        ao = abs(blended.g - depth) < kSameSurface * depth ? blended.r : upsampledAo(depth);
    }
    if (aoOnly > 0.5) { fragColour = vec4(vec3(ao), 1.0); return; }

    // Smoke in front of the surface (or the sky) seen here, from the half-resolution march.
    vec4 smoke = vec4(0.0, 0.0, 0.0, 1.0);
    if (smokePresent > 0.5) {
        smoke = texture(smokeMap, vUv);
        if (smoke.a < 0.999) smoke = upsampledSmoke(depth, smoke);
    }
    vec3 smokeLight = smoke.rgb;
    float smokeT = smoke.a;

    vec3 shown = texelFetch(colourMap, pixel, 0).rgb;
    // Nothing to change: AO within 1.5 % of open takes less than one 8-bit level off the ambient
    // light, so most of an open floor skips the tone-mapping round trip below.
    if (ao > 0.985 && smokeT > 0.999) { fragColour = vec4(shown, 1.0); return; }
    // 1/1024: white stays finite when undone (1 - exp(-x) reaches 1 - 1/1024 at x = 6.9)
    vec3 light = -log(max(vec3(1.0) - pow(shown, vec3(2.2)), vec3(1.0 / 1024.0)));
    light *= vec3(1.0) - texelFetch(ambientMap, pixel, 0).rgb * (1.0 - ao);
    light = light * smokeT + smokeLight;
    fragColour = vec4(pow(vec3(1.0) - exp(-light), vec3(1.0 / 2.2)), 1.0);
}
