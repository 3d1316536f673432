// The back-lit signs' second mode, `--sign-mode meshuggah` (issue 15, item 4): the seed's
// Meshuggah (Carsten Wenzel, 2001) for a side-by-side comparison with the ray-marched shafts.
//
// What the seed did: the text is an 8-bit bitmap mask on a plane; rays from the light are cast to
// the plane (one ray/plane test each), cut where they hit a glyph, and drawn additively as thin
// lines with a 1D black-white-black gradient across each for soft edges, the mask's 8-bit value
// fading the rays near a glyph's edge; three steps (light -> plane, the mask, plane -> infinity)
// keep the depth order. Right only for its fixed view.
//
// Here, per sign (built once, and again when its bullet holes change):
//   - the mask: a coarse 8-bit copy of the letters' distance field (and the holes), one texel every
//     `spacing` metres of the plate (letterHeight / 32, coarser until at most kMaxRays rays pass):
//     coverage = clamp(0.5 + distance / spacing, 0, 1) quantised to 0..255, as the seed's 8-bit
//     bitmap; a texel of coverage 0 casts no ray;
//   - one ray per open texel, from the lamp through the texel's centre (the ray/plane test is the
//     texel itself: the grid lies on the plane), drawn from the plate to the sign's `range` as a
//     quad strip whose two ends the vertex shader turns to face the camera (per-vertex ray
//     direction; the buffer is static, nothing is rebuilt per frame). The strip's half width is the
//     texel spacing, widened with the distance from the lamp as the texel's cone is, so the
//     neighbours' tents (1 - |across|: the black-white-black gradient) add up to a continuous beam;
//   - step 1 (lamp -> plate) is not drawn: the lamp sits in a closed housing (sign_light.h: no light
//     leaves but through the plate), and the ray-march draws nothing there either; step 2 is the
//     plate, which already glows (sign_plate.frag); step 3 is the rays.
//
// Depth: the rays are drawn into the frame's HDR `lit` after the lighting quad (frame::kEffectsQueue),
// where the hardware depth buffer does not hold the scene's depth on llvmpipe
// (engine_ext/frame/README.md, "Liquids"); the fragment shader tests each fragment against the
// G-buffer's `gbufferDepth` (bound by Frame::addSceneMaterial, as liquid.frag does), so the drawing
// order does not matter (the blend adds). Geometry between the lamp and a point (the pillar) is the
// lamp's shadow map's (SignRender draws it per frame in this mode too): a fragment farther from the
// lamp than the first surface the map saw is discarded, so a ray stops at the first wall it hits.
#pragma once

#include "signs/meshuggah_rays.h"
#include "signs/sign_light.h"

#include <OgreMaterial.h>
#include <OgreMatrix4.h>
#include <OgreTexture.h>

#include <cstddef>
#include <vector>

namespace Ogre {
class ManualObject;
class SceneManager;
class SceneNode;
}  // namespace Ogre

namespace obscura::signs {

class Meshuggah {
public:
    Meshuggah(Ogre::SceneManager& scene, const std::vector<SignSpec>& specs, const std::vector<SignMask>& masks);
    ~Meshuggah();
    Meshuggah(const Meshuggah&) = delete;
    Meshuggah& operator=(const Meshuggah&) = delete;

    // Sign i's holes changed: its rays are rebuilt.
    void setHoles(std::size_t i, const std::vector<Hole>& holes);
    // Once a frame: shown (`on`) for the signs lit this frame, chosen[k] with its lamp's shadow map
    // shadowMaps[k] (world -> clip: shadowMatrices[k]); hidden otherwise. `haze`: per metre.
    void update(bool on, const std::vector<std::size_t>& chosen, const std::vector<Ogre::TexturePtr>& shadowMaps,
                const std::vector<Ogre::Matrix4>& shadowMatrices, float haze);
    // The rays' materials (one per sign), for Frame::addSceneMaterial: they read gbufferDepth.
    const std::vector<Ogre::MaterialPtr>& materials() const { return materials_; }
    std::size_t rayCount(std::size_t i) const { return rayCounts_[i]; }

private:
    void build(std::size_t i, const std::vector<Hole>& holes);

    Ogre::SceneManager& scene_;
    const std::vector<SignSpec>& specs_;
    const std::vector<SignMask>& masks_;
    std::vector<Ogre::MaterialPtr> materials_;
    std::vector<Ogre::ManualObject*> rays_;
    std::vector<Ogre::SceneNode*> nodes_;
    std::vector<std::size_t> rayCounts_;
    std::vector<double> spacing_;  // the grid's, metres
};

}  // namespace obscura::signs
