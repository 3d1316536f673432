// What the frame's C++ (engine_ext/frame) and its GLSL (shaders/frame, and every technique's
// shaders that read the G-buffer) agree on, in one place: plain #defines valid in both languages.
// Included by C++ as "frame/frame_shared.h" (shaders/ is on the include path) and by GLSL as
// "frame_shared.h" (shaders/frame is an OGRE resource location).
#ifndef OBSCURA_FRAME_SHARED_H
#define OBSCURA_FRAME_SHARED_H

// The G-buffer, written by every opaque material in the GBuffer scheme (gbuffer_out.glsl):
//   FRAME_GBUFFER_ALBEDO  A8B8G8R8   albedo as its texture stores it (gamma 2.2), a unused
//   FRAME_GBUFFER_NORMAL  A8B8G8R8   view-space normal packed to 0..1; a = how much of the sky
//                                    hemisphere the normal faces (0.5 + 0.5 world n.y)
//   FRAME_GBUFFER_DEPTH   FLOAT32_R  linear view depth in metres, 0 = nothing drawn (sky)
//   FRAME_GBUFFER_LIGHT   FLOAT16_RGBA direct irradiance (sun with its shadow, point lights), HDR;
//                                    a = the sun's visibility here (its shadow; 0 facing away)
//   FRAME_GBUFFER_AMBIENT R11G11B10F the indirect irradiance (sky seen, bounced light; the baked
//                                    lightmap's, or the irradiance volume's: engine_ext/lightbake),
//                                    which AO darkens; 11 bits of float a channel is the lightmap's
//                                    smooth light without banding, at 4 bytes
// 24 bytes a pixel. Light is irradiance, not radiance: the lighting pass multiplies it by the
// albedo, so a decal that changes the albedo changes what the light makes of it.
#define FRAME_GBUFFER_ALBEDO 0
#define FRAME_GBUFFER_NORMAL 1
#define FRAME_GBUFFER_DEPTH 2
#define FRAME_GBUFFER_LIGHT 3
#define FRAME_GBUFFER_AMBIENT 4
#define FRAME_GBUFFER_TARGETS 5
// The split G-buffer's (on GPUs with fewer targets) first part holds the slots below this one.
#define FRAME_GBUFFER_SPLIT 2

// How fast a neighbour stops counting as the same surface in the depth-aware filters (AO blur, AO
// and volume upsampling): weight exp(-dz/z * 50), so a tap 2 % deeper keeps 37 % of its weight and
// one 10 % deeper 0.7 % (sharp: the AO buffer is at a quarter of the resolution, and a soft edge
// there shows as a halo round every silhouette).
#define FRAME_DEPTH_SHARPNESS 50.0
// Relative depth within which one bilinear tap of an upsampled buffer is taken as is (no
// silhouette among its four texels): 2 cm at 1 m, 20 cm at 10 m.
#define FRAME_SAME_SURFACE 0.02

// The level's env_ambient areas the lighting pass scales the ambient in (Frame::setAmbientAreas;
// map_lights.h ambientScaleAt): 8, a box test each per pixel; a level with more warns at load.
#define FRAME_MAX_AMBIENT_AREAS 8
// A point this far outside an area's face counts as on it (map::kAmbientAreaGrace).
#define FRAME_AMBIENT_AREA_GRACE 0.02

// Resolutions of the frame's own buffers that techniques' passes read: the volumetrics' light and
// transmittance are kept at half the width and height (a full-resolution march cost ~4x on
// llvmpipe for no visible gain on smooth smoke).
#define FRAME_VOLUME_SCALE 0.5
// ... and marched at a quarter: each frame one pixel of every 2x2 block of the half-resolution
// buffer, the one at the frame's phase (FRAME_VOLUME_PHASES, a 2x2 cycle: (0,0), (1,1), (1,0),
// (0,1), the diagonal first so two frames already cover both checker colours); the other three
// are last frames' values reprojected and clamped to the new samples around them
// (shaders/frame/volume_resolve.frag). A quarter of the march's cost; a still view converges to
// the half-resolution march in FRAME_VOLUME_PHASES frames.
#define FRAME_VOLUME_SAMPLE_SCALE 0.25
#define FRAME_VOLUME_PHASES 4

#endif
