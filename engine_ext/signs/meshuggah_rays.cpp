// See meshuggah_rays.h.
#include "signs/meshuggah_rays.h"

#include <algorithm>
#include <cmath>

namespace obscura::signs {

namespace {
// The grid's finest spacing, as a share of the letter height: 32 texels a letter (the seed's mask
// was a small bitmap; coarser shows the rays as lines, finer costs fill).
constexpr double kTexelsPerLetter = 32;

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}
}  // namespace

std::vector<MeshuggahRay> meshuggahRays(const SignSpec& s, const SignMask& m, const std::vector<Hole>& holes, double& spacing) {
    spacing = s.letterHeight / kTexelsPerLetter;
    const double cosCone = std::cos(s.coneDegrees * 3.14159265358979 / 180), cosInner = std::cos(0.85 * s.coneDegrees * 3.14159265358979 / 180);
    for (;;) {
        std::vector<MeshuggahRay> rays;
        const int nx = std::max(1, static_cast<int>(std::floor(2 * m.halfWidth / spacing)));
        const int ny = std::max(1, static_cast<int>(std::floor(2 * m.halfHeight / spacing)));
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                // Texel centres, the grid centred on the plate.
                const double x = (i - 0.5 * (nx - 1)) * spacing, y = (0.5 * (ny - 1) - j) * spacing;
                double d = openDistance(m, holes, x, y);
                d = std::min({d, m.halfWidth - std::abs(x), m.halfHeight - std::abs(y)});
                // The 8-bit mask: the distance field's coverage of the texel, quantised.
                const auto coverage = static_cast<unsigned char>(std::lround(255 * std::clamp(0.5 + d / spacing, 0.0, 1.0)));
                if (coverage == 0) continue;
                const Vec3 q = s.centre + s.right * x + s.up * y;
                const Vec3 toQ = q - s.lamp;
                const double a = length(toQ);
                const Vec3 dir = toQ * (1 / a);
                // The cone fades the ray as it does the light (sign_light.h's throughSign).
                const double cone = smoothstep(cosCone, cosInner, dot(dir, s.facing));
                const auto faded = static_cast<unsigned char>(std::lround(coverage * cone));
                if (faded == 0 || a + kStartOffset >= s.range) continue;
                rays.push_back({q + dir * kStartOffset, dir, s.range - a - kStartOffset, faded});
            }
        if (rays.size() <= kMaxRays) return rays;
        spacing *= 1.25;
    }
}

}  // namespace obscura::signs
