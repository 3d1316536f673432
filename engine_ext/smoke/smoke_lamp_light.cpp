// See smoke_lamp_light.h.
#include "smoke/smoke_lamp_light.h"

#include <algorithm>
#include <cmath>

namespace obscura::smoke {

void lampLight(const GridInfo& g, const SmokeBox& occupied, const std::vector<SmokeLamp>& lamps,
               std::size_t shadowedLevelLamps, const std::vector<float>& lampT, std::vector<float>& out) {
    const std::size_t n = g.cells();
    out.assign(kLampLightTexels * 4 * n, 0.f);
    if (lamps.empty()) return;
    float* A = out.data();
    float* B = out.data() + 4 * n;
    // The cells whose centres lie in the occupied box widened by a cell: what trilinear taps there reach.
    int lo[3], hi[3];
    const double o[3] = {occupied.min.x - g.origin.x, occupied.min.y - g.origin.y, occupied.min.z - g.origin.z};
    const double s[3] = {occupied.size.x, occupied.size.y, occupied.size.z};
    const int dims[3] = {g.nx, g.ny, g.nz};
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::max(0, static_cast<int>(std::floor(o[a] / g.cellSize)) - 1);
        hi[a] = std::min(dims[a] - 1, static_cast<int>(std::ceil((o[a] + s[a]) / g.cellSize)) + 1);
    }
    const bool shadows = !lampT.empty();
    for (int k = lo[2]; k <= hi[2]; ++k)
        for (int j = lo[1]; j <= hi[1]; ++j)
            for (int i = lo[0]; i <= hi[0]; ++i) {
                const std::size_t c = g.index(i, j, k);
                const Vec3 p = g.cellCentre(i, j, k);
                Vec3 total, single, mean;
                double weight = 0;
                for (std::size_t l = 0; l < lamps.size(); ++l) {
                    const Vec3 toLamp = lamps[l].position - p;
                    const double d = length(toLamp);
                    const double f = std::max(1.0 - d / lamps[l].range, 0.0);
                    if (f <= 0) continue;
                    const double T = shadows && l < shadowedLevelLamps && l < 4 ? lampT[4 * c + l] : 1.0;
                    const Vec3 a = lamps[l].colour * (f * f * T);
                    const Vec3 light = a + lamps[l].colour * (f * f * kLampMultipleWeight * std::sqrt(T));
                    total = total + light;
                    single = single + a;
                    const double w = 0.2126 * light.x + 0.7152 * light.y + 0.0722 * light.z;
                    // At the lamp's own position no direction: it counts for the light, not the mean.
                    if (d > 1e-9) mean = mean + toLamp * (w / d);
                    weight += w;
                }
                if (weight <= 0) continue;
                const double lum = 0.2126 * total.x + 0.7152 * total.y + 0.0722 * total.z;
                const double lumSingle = 0.2126 * single.x + 0.7152 * single.y + 0.0722 * single.z;
                A[4 * c] = static_cast<float>(total.x);
                A[4 * c + 1] = static_cast<float>(total.y);
                A[4 * c + 2] = static_cast<float>(total.z);
                A[4 * c + 3] = static_cast<float>(lum > 0 ? lumSingle / lum : 0.0);
                B[4 * c] = static_cast<float>(mean.x / weight);
                B[4 * c + 1] = static_cast<float>(mean.y / weight);
                B[4 * c + 2] = static_cast<float>(mean.z / weight);
            }
}

}  // namespace obscura::smoke
