// See probe_grid.h.
#include "lightbake/probe_grid.h"

#include <algorithm>
#include <cmath>

namespace obscura::lightbake {

void ProbeGrid::sample(const Vec3& p, Vec3& irradianceUp, Vec3& irradianceDown) const {
    irradianceUp = irradianceDown = {};
    if (count() == 0) return;
    const Vec3 g = (p - origin) / cell;
    const double gx = std::clamp(g.x, 0.0, nx - 1.0), gy = std::clamp(g.y, 0.0, ny - 1.0), gz = std::clamp(g.z, 0.0, nz - 1.0);
    const int x0 = std::min(static_cast<int>(gx), nx - 1), y0 = std::min(static_cast<int>(gy), ny - 1),
              z0 = std::min(static_cast<int>(gz), nz - 1);
    const double fx = gx - x0, fy = gy - y0, fz = gz - z0;
    for (int c = 0; c < 8; ++c) {
        const int x = std::min(x0 + (c & 1), nx - 1), y = std::min(y0 + ((c >> 1) & 1), ny - 1), z = std::min(z0 + (c >> 2), nz - 1);
        const double w = ((c & 1) ? fx : 1 - fx) * (((c >> 1) & 1) ? fy : 1 - fy) * ((c >> 2) ? fz : 1 - fz);
        const std::size_t m = (static_cast<std::size_t>(x) + nx * (static_cast<std::size_t>(y) + ny * z)) * 3;
        irradianceUp += Vec3{up[m], up[m + 1], up[m + 2]} * w;
        irradianceDown += Vec3{down[m], down[m + 1], down[m + 2]} * w;
    }
}

}  // namespace obscura::lightbake
