#version 330 core
// Stores -height/10^4, where height is the caster's distance towards the sun (metres). The map is
// cleared to 1.0 = "nothing here", lower than any caster inside +-10 km, so uncovered texels read
// as lit; storing world-space height (not NDC depth) makes the test independent of the shadow
// camera's near/far planes, which OGRE chooses per frame.
// Fence casters (Obscura/ShadowCasterAlphaTest) discard their holes as level.frag does, so the
// shadow on the floor has the holes too; alphaCutoff 0 (every other caster) samples nothing.
uniform sampler2D albedoMap;
uniform float alphaCutoff;
in float vHeight;
in vec2 vUv;
out vec4 fragColour;
void main()
{
    if (alphaCutoff > 0.0 && texture(albedoMap, vUv).a < alphaCutoff) discard;
    fragColour = vec4(-vHeight * 1e-4, 0.0, 0.0, 1.0);
}
