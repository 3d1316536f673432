#version 330 core
// `--sign-mode meshuggah` (engine_ext/signs/meshuggah.h): one ray of a sign's 8-bit mask, a quad
// strip from the plate to the range whose ends turn to face the camera: each vertex moves by its
// half width along cross(ray, towards the eye), so the strip is seen broadside from any view
// (end-on it shrinks to the ray's cross-section, as a line does).
uniform mat4 worldViewProj;
uniform mat4 world;
uniform vec3 cameraPosition;  // world
// The strip's half width is at most this share of its distance to the eye (0.01 rad, ~8 pixels at
// 1280 wide and a 90 degree fov): a ray passing by the camera would otherwise cover the screen (its
// texel's cone is centimetres wide), the overdraw that costs the most on llvmpipe. It binds only
// within a metre or two of the eye; the light it drops there is part of the mode's error.
const float kMaxHalfAngle = 0.01;
in vec4 vertex;               // the end on the ray's axis
in vec3 normal;               // the ray's direction (unit, from the lamp)
in vec2 uv0;                  // across (-1 | +1), distance from the lamp (m)
in vec2 uv1;                  // coverage (0..1), half width at this end (m)
out vec3 vWorldPos;
out float vAcross;
out float vLampDistance;
out float vCoverage;
out float vHalfWidth;
out vec3 vDirection;
void main()
{
    vec3 p = (world * vertex).xyz;
    vec3 dir = normalize(mat3(world) * normal);
    vec3 side = cross(dir, cameraPosition - p);
    float l = length(side);
    // Looking straight down the ray: any perpendicular will do.
    side = l > 1e-6 ? side / l : normalize(cross(dir, abs(dir.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    float halfWidth = min(uv1.y, kMaxHalfAngle * length(cameraPosition - p));
    vec3 offset = side * (uv0.x * halfWidth);
    vWorldPos = p + offset;
    vAcross = uv0.x;
    vLampDistance = uv0.y;
    vCoverage = uv1.x;
    vHalfWidth = uv1.y;  // the cone's: the light (meshuggah.frag) is not scaled by the cap
    vDirection = dir;
    gl_Position = worldViewProj * vec4(vertex.xyz + mat3(inverse(world)) * offset, 1.0);
}
