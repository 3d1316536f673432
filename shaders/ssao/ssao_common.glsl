// Shared by the AO modes: G-buffer access and projection of view-space points to texture space.
uniform sampler2D gbufferPosition;  // view-space position, w = 1 on geometry
uniform sampler2D gbufferNormal;    // view-space normal
uniform sampler2D noiseMap;         // 4x4 random unit vectors (packed to 0..1)
uniform vec2 projScale;             // projection matrix [0][0] and [1][1]
uniform float flipY;                // 1 when render textures are stored upside down
uniform float radius;               // metres
uniform float intensity;
uniform vec3 kernel[32];
uniform float sampleCount;

vec2 projectToUv(vec3 p)
{
    vec2 ndc = projScale * p.xy / -p.z;
    vec2 uv = ndc * 0.5 + 0.5;
    if (flipY > 0.5) uv.y = 1.0 - uv.y;
    return uv;
}

// Random rotation per pixel from a tiled 4x4 texture (interleaved sampling).
vec3 pixelNoise()
{
    return normalize(texture(noiseMap, gl_FragCoord.xy / 4.0).xyz * 2.0 - 1.0);
}

// 1 if the scene surface seen at q's pixel lies in front of q (q is inside geometry), weighted
// down when that surface is far outside the radius (it only hides q from view: a false occluder).
float occluderAt(vec3 q, float centreZ)
{
    vec2 uv = projectToUv(q);
    if (uv.x < 0.0 || uv.x > 1.0 || uv.y < 0.0 || uv.y > 1.0) return 0.0;
    vec4 s = texture(gbufferPosition, uv);
    if (s.w < 0.5) return 0.0;  // sky
    float inFront = s.z >= q.z + 0.02 * radius ? 1.0 : 0.0;
    float range = smoothstep(0.0, 1.0, radius / max(abs(centreZ - s.z), 1e-4));
    return inFront * range;
}
