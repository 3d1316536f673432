// Each full-screen pixel's view ray, from the quad's uv (not gl_FragCoord: the viewport may be a
// window while the buffers are render textures stored upside down). The uniforms are set by
// frame::setViewRay (engine_ext/frame/technique.h).
#ifndef OBSCURA_VIEW_RAY_GLSL
#define OBSCURA_VIEW_RAY_GLSL
uniform vec2 projScale;    // projection matrix [0][0] and [1][1]
uniform float flipY;       // 1 when render textures are stored upside down
uniform mat4 inverseView;  // view -> world

// The view-space point at view depth 1 (z = -1) seen through uv; times a linear depth, the
// surface's view-space position.
vec3 viewRayAt(vec2 uv)
{
    vec2 ndc = vec2(uv.x, flipY > 0.5 ? 1.0 - uv.y : uv.y) * 2.0 - 1.0;
    return vec3(ndc / projScale, -1.0);
}
#endif
