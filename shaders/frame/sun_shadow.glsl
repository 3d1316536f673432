// The sun's shadow map (OGRE integrated texture shadows, engine_ext/render/level_lighting.cpp):
// each texel holds -height/10^4 of the caster nearest the sun, height = its distance towards the
// sun (m), cleared to 1.0 where there is none (shaders/level/shadow_caster.frag). Tested by the
// level's surfaces (shaders/level/level.frag, which OGRE binds) and by the smoke's march
// (shaders/smoke/smoke_march.glsl, bound by engine_ext/smoke/smoke_render.cpp).
#ifndef SUN_SHADOW_GLSL
#define SUN_SHADOW_GLSL
uniform sampler2D sunShadowMap;  // -height/10^4 of the caster nearest the sun (shadow_caster.frag)
uniform vec4 sunShadowTexel;     // 1/width, 1/height, width, height of sunShadowMap

// The fraction of the sun reaching a receiver `height` metres towards the sun (its bias included)
// at p, its place on the map (xy in [0, 1]): 2x2 percentage-closer filtering. Outside the map: lit.
float sunShadowLit(vec2 p, float height)
{
    if (p.x <= 0.0 || p.x >= 1.0 || p.y <= 0.0 || p.y >= 1.0) return 1.0;
    float receiver = -height * 1e-4;
    float lit = 0.0;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            vec2 uv = p + (vec2(x, y) - 0.5) * sunShadowTexel.xy;
            lit += (receiver <= texture(sunShadowMap, uv).r) ? 1.0 : 0.0;
        }
    return lit * 0.25;
}
#endif
