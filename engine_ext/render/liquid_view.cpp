// See liquid_view.h.
#include "render/liquid_view.h"

#include "render/ogre_convert.h"

#include <OgreGpuProgramManager.h>

#include <cmath>
#include <stdexcept>

namespace obscura::render {

LiquidMedium liquidMedium(map::LiquidKind kind) {
    // Fog colours are linear HDR, about what the lit scene around the pool sends (exposure 1.6
    // puts 0.06 near sRGB 0.3). Densities: water fades to 1/e in 6 m (a murky pool: its floor shows
    // at 2 m, the far wall at 10 m is mostly gone); slime in 2.5 m; lava in 0.4 m (you see your
    // hand and nothing more). Tints: water blue-green, slime green, lava orange (Quake's view
    // blends, v_cshift: slime green, lava orange; its water is brown, ours the brief's blue-green).
    switch (kind) {
        case map::LiquidKind::Water:
        case map::LiquidKind::Teleport: return {{0.4, 0.75, 0.8}, {0.012, 0.05, 0.06}, 1.0 / 6.0};
        case map::LiquidKind::Slime: return {{0.35, 0.8, 0.2}, {0.02, 0.07, 0.01}, 1.0 / 2.5};
        case map::LiquidKind::Lava: return {{1.0, 0.4, 0.1}, {0.6, 0.15, 0.02}, 1.0 / 0.4};
        case map::LiquidKind::None: break;
    }
    return {};
}

void setLiquidView(double simSeconds, map::LiquidKind cameraIn) {
    auto& gpm = Ogre::GpuProgramManager::getSingleton();
    const auto& all = gpm.getAvailableSharedParameters();
    if (all.find("ObscuraLiquid") == all.end())
        throw std::runtime_error("shared_params ObscuraLiquid is missing (media/frame/frame.program)");
    Ogre::GpuSharedParametersPtr p = gpm.getSharedParameters("ObscuraLiquid");
    // The warp is periodic in 2 pi seconds: wrap the time so a float keeps its precision in a long run.
    constexpr double kTwoPi = 6.28318530717958647692;
    p->setNamedConstant("liquidTime", static_cast<float>(std::fmod(simSeconds, kTwoPi)));
    const LiquidMedium m = liquidMedium(cameraIn);
    p->setNamedConstant("mediumTint", toOgre(m.tint));
    p->setNamedConstant("mediumFog", toOgre(m.fog));
    p->setNamedConstant("mediumDensity", static_cast<float>(m.density));
}

}  // namespace obscura::render
