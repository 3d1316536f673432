// See quake_light.h.
#include "map/quake_light.h"

#include <algorithm>
#include <cmath>

namespace obscura::map {

namespace {
// The formula's fraction of the value at distance `metres` (1 at the source for linear, the inverse
// laws' S/x or S^2/x^2, ...), before the gate.
double fraction(const LevelLight& l, double metres) {
    const double x = metres * l.unitsPerMetreScaled;  // Quake's scaled distance, map units
    const double xi = std::max(x, kMinInverseDistance);
    switch (l.formula) {
        case LightFormula::Linear: {
            const double f = l.radius > 0 ? std::clamp(1.0 - metres / l.radius, 0.0, 1.0) : 0.0;
            return std::pow(f, l.falloffExponent);
        }
        case LightFormula::Inverse: return kInverseLightScale / xi;
        case LightFormula::InverseSquare: return kInverseLightScale * kInverseLightScale / (xi * xi);
        case LightFormula::InverseSquareA: {
            const double s = x + kInverseLightScale;
            return kInverseLightScale * kInverseLightScale / (s * s);
        }
        case LightFormula::None:
        case LightFormula::LocalMinimum: return 1.0;
    }
    return 0.0;
}

bool gated(LightFormula f) {
    return f == LightFormula::Inverse || f == LightFormula::InverseSquare || f == LightFormula::InverseSquareA;
}
}  // namespace

double lightAtDistance(const LevelLight& l, double metres) {
    const double scale = l.intensity / kQuakeLightUnit;
    if (!gated(l.formula)) return scale * fraction(l, metres);
    // The gate subtracted from the magnitude: no edge where the light is cut.
    const double magnitude = std::max(std::fabs(scale) * fraction(l, metres) - kLightGate, 0.0);
    return scale < 0 ? -magnitude : magnitude;
}

double angleFactor(const LevelLight& l, double cosine) {
    if (cosine <= 0) return 0.0;  // behind the surface: nothing, whatever the scale
    return (1.0 - l.angleScale) + l.angleScale * cosine;
}

double spotFactor(const LevelLight& l, double cosine) {
    if (!l.spot) return 1.0;
    if (cosine < l.spotCosOuter) return 0.0;
    if (l.spotCosInner <= l.spotCosOuter) return 1.0;  // no soft cone: a hard edge
    return std::clamp((cosine - l.spotCosOuter) / (l.spotCosInner - l.spotCosOuter), 0.0, 1.0);
}

double lightAt(const LevelLight& l, const Vec3& point, const Vec3& normal) {
    const Vec3 toLight = l.position - point;
    const double d = length(toLight);
    if (d >= lightReach(l, 1e300)) return 0.0;
    const Vec3 dir = d > 1e-9 ? toLight / d : normal;
    if (l.formula == LightFormula::LocalMinimum) return lightAtDistance(l, d);
    return lightAtDistance(l, d) * angleFactor(l, dot(normal, dir)) * spotFactor(l, dot(l.spotDirection, -dir));
}

double lightReach(const LevelLight& l, double levelSize) {
    const double value = std::fabs(l.intensity) / kQuakeLightUnit;
    const double k = l.unitsPerMetreScaled;
    switch (l.formula) {
        case LightFormula::Linear: return l.radius;
        case LightFormula::Inverse: return std::min(value * kInverseLightScale / kLightGate / k, levelSize);
        case LightFormula::InverseSquare: return std::min(kInverseLightScale * std::sqrt(value / kLightGate) / k, levelSize);
        case LightFormula::InverseSquareA:
            return std::clamp((kInverseLightScale * std::sqrt(value / kLightGate) - kInverseLightScale) / k, 0.0, levelSize);
        case LightFormula::None:
        case LightFormula::LocalMinimum: return levelSize;
    }
    return 0.0;
}

}  // namespace obscura::map
