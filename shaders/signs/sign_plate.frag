#version 330 core
// A back-lit sign's plate in the G-buffer (engine_ext/signs/sign_render.cpp builds it: the front
// face carries the mask's uv, the back and the edges uv -1). On the front, where the letters'
// distance field (or a bullet hole) is open, the lamp behind shines through a diffuser: the pixel
// is a light grey whose direct light is the diffuser's glow; elsewhere the plate's colour, unlit by
// the lamp (it is behind the plate). The edge is antialiased over one pixel's footprint of the field.
#include "signs_shared.h"
in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
in vec4 vShadowPos;
uniform sampler2D plateMask;               // metres, > 0 inside a letter
uniform vec3 plateColour;                  // linear albedo of the plate
uniform vec3 plateGlow;                    // the open diffuser's light, linear (HDR)
uniform vec2 plateHalf;                    // half width, half height, metres
uniform float plateHoleCount;
uniform vec4 plateHoles[SIGN_MAX_HOLES];   // x, y (plate metres), radius
#include "gbuffer_out.glsl"
#include "baked_ambient.glsl"  // the plate's ambient: the irradiance volume (it has no lightmap)
const vec3 kDiffuserAlbedo = vec3(0.85);   // opal acrylic, light grey

void main()
{
    vec3 n = normalize(vNormal);
    float coverage = 0.0;
    if (vUv.x >= 0.0) {
        vec2 xy = vec2((vUv.x - 0.5) * 2.0 * plateHalf.x, (0.5 - vUv.y) * 2.0 * plateHalf.y);
        float open = texture(plateMask, vUv).r;
        int holes = int(plateHoleCount);
        for (int h = 0; h < SIGN_MAX_HOLES; ++h) {
            if (h >= holes) break;
            open = max(open, plateHoles[h].z - length(xy - plateHoles[h].xy));
        }
        coverage = clamp(0.5 + open / max(fwidth(open), 1e-5), 0.0, 1.0);
    }
    vec3 albedo = mix(pow(plateColour, vec3(1.0 / 2.2)), kDiffuserAlbedo, coverage);
    writeGBuffer(albedo, plateGlow * coverage, 0.0, probeAmbient(vWorldPos, n), vWorldPos, n);
}
