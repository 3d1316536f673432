// The light bake on the GPU (OGRE glue): the lightmaps as two RGBA16F textures and the irradiance
// volume as one 3D texture, bound by name on every material with a `lightmapDirect`,
// `lightmapIndirect` or `lightProbes` texture unit (the level's, the sign plates', the smoke's
// march), and the volume's placement in the shared parameters ObscuraBakedLight. RAII: the
// textures go with the object, and the shared parameters return to "no bake".
#pragma once

#include "lightbake/light_bake.h"

#include <OgreTexture.h>

namespace obscura::lightbake {

class BakedLightView {
public:
    explicit BakedLightView(const LightBake& bake);
    ~BakedLightView();
    BakedLightView(const BakedLightView&) = delete;
    BakedLightView& operator=(const BakedLightView&) = delete;

    // Binds the textures on a material made after the view (one not cloned from a bound one).
    void bind(Ogre::Material& material) const;

private:
    Ogre::TexturePtr direct_, indirect_, probes_;
};

}  // namespace obscura::lightbake
