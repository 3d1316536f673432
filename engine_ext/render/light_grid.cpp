// See light_grid.h.
#include "render/light_grid.h"

#include "map/quake_light.h"

#include <algorithm>
#include <cmath>

namespace obscura::render {

namespace {
bool gated(map::LightFormula f) {
    return f == map::LightFormula::Inverse || f == map::LightFormula::InverseSquare || f == map::LightFormula::InverseSquareA;
}

// Distance from `p` to the box [lo, hi].
double boxDistance(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    const Vec3 q{std::clamp(p.x, lo.x, hi.x), std::clamp(p.y, lo.y, hi.y), std::clamp(p.z, lo.z, hi.z)};
    return length(p - q);
}

void put(std::vector<float>& t, std::size_t texel, double a, double b, double c, double d) {
    t[texel * 4 + 0] = static_cast<float>(a);
    t[texel * 4 + 1] = static_cast<float>(b);
    t[texel * 4 + 2] = static_cast<float>(c);
    t[texel * 4 + 3] = static_cast<float>(d);
}
}  // namespace

LightGrid buildLightGrid(const map::Level& level) {
    LightGrid g;
    map::Aabb box = level.bounds;
    for (const auto& l : level.lights) box.extend(l.position);
    if (box.empty()) box.min = box.max = Vec3{0, 0, 0};
    const Vec3 size = box.max - box.min;
    const double volume = std::max(size.x, 1.0) * std::max(size.y, 1.0) * std::max(size.z, 1.0);
    g.cell = std::max(kMinLightGridCell, std::cbrt(volume / static_cast<double>(kMaxLightGridCells)));
    const auto cells = [&](double extent) { return std::max(1, static_cast<int>(std::ceil(extent / g.cell))); };
    g.nx = cells(size.x), g.ny = cells(size.y), g.nz = cells(size.z);
    while (static_cast<std::size_t>(g.nx) * g.ny * g.nz > kMaxLightGridCells) {  // ceil's rounding
        g.cell *= 1.05;
        g.nx = cells(size.x), g.ny = cells(size.y), g.nz = cells(size.z);
    }
    g.origin = box.min;

    // Which lights reach each cell: the light's sphere (reach) meets the cell's box.
    const std::size_t n = static_cast<std::size_t>(g.nx) * g.ny * g.nz;
    std::vector<std::vector<int>> lists(n);
    const double levelSize = level.bounds.empty() ? 1.0 : length(level.bounds.max - level.bounds.min);
    for (std::size_t i = 0; i < level.lights.size(); ++i) {
        const map::LevelLight& l = level.lights[i];
        const double r = map::lightReach(l, levelSize);
        if (r <= 0) continue;
        const auto lo = [&](double v, double o, int count) { return std::clamp(static_cast<int>(std::floor((v - o) / g.cell)), 0, count - 1); };
        const int x0 = lo(l.position.x - r, g.origin.x, g.nx), x1 = lo(l.position.x + r, g.origin.x, g.nx);
        const int y0 = lo(l.position.y - r, g.origin.y, g.ny), y1 = lo(l.position.y + r, g.origin.y, g.ny);
        const int z0 = lo(l.position.z - r, g.origin.z, g.nz), z1 = lo(l.position.z + r, g.origin.z, g.nz);
        for (int z = z0; z <= z1; ++z)
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) {
                    const Vec3 cLo = g.origin + Vec3{x * g.cell, y * g.cell, z * g.cell};
                    if (boxDistance(l.position, cLo, cLo + Vec3{g.cell, g.cell, g.cell}) <= r)
                        lists[static_cast<std::size_t>(x) + static_cast<std::size_t>(g.nx) * (y + static_cast<std::size_t>(g.ny) * z)]
                            .push_back(static_cast<int>(i));
                }
    }
    for (const auto& list : lists) {
        g.indices += list.size();
        g.mostInACell = std::max(g.mostInACell, list.size());
    }

    g.headerBase = static_cast<int>(level.lights.size()) * kLightTexels;
    g.indexBase = g.headerBase + static_cast<int>(n);
    const std::size_t total = static_cast<std::size_t>(g.indexBase) + g.indices;
    const std::size_t rows = std::max<std::size_t>(1, (total + kLightGridWidth - 1) / kLightGridWidth);
    g.texels.assign(rows * kLightGridWidth * 4, 0.0f);
    for (std::size_t i = 0; i < level.lights.size(); ++i) {
        const map::LevelLight& l = level.lights[i];
        const double k = l.intensity / map::kQuakeLightUnit;
        const double gate = gated(l.formula) && k != 0 ? map::kLightGate / std::fabs(k) : 0.0;
        const std::size_t t = i * kLightTexels;
        put(g.texels, t + 0, l.position.x, l.position.y, l.position.z, map::lightReach(l, levelSize));
        put(g.texels, t + 1, l.colour.x * k, l.colour.y * k, l.colour.z * k, static_cast<int>(l.formula) + (l.spot ? kSpotFlag : 0));
        put(g.texels, t + 2, l.unitsPerMetreScaled, gate, l.angleScale, l.falloffExponent);
        put(g.texels, t + 3, l.spotDirection.x, l.spotDirection.y, l.spotDirection.z, l.spotCosInner);
        put(g.texels, t + 4, l.spotCosOuter, 0, 0, 0);
    }
    std::size_t next = 0;
    for (std::size_t c = 0; c < n; ++c) {
        put(g.texels, static_cast<std::size_t>(g.headerBase) + c, static_cast<double>(next), static_cast<double>(lists[c].size()), 0, 0);
        for (int light : lists[c]) g.texels[(static_cast<std::size_t>(g.indexBase) + next++) * 4] = static_cast<float>(light);
    }
    return g;
}

std::vector<int> LightGrid::lightsAt(const Vec3& p) const {
    const Vec3 q = (p - origin) / cell;
    const int x = static_cast<int>(std::floor(q.x)), y = static_cast<int>(std::floor(q.y)), z = static_cast<int>(std::floor(q.z));
    if (x < 0 || y < 0 || z < 0 || x >= nx || y >= ny || z >= nz) return {};
    const std::size_t c = static_cast<std::size_t>(x) + static_cast<std::size_t>(nx) * (y + static_cast<std::size_t>(ny) * z);
    const float* h = &texels[(static_cast<std::size_t>(headerBase) + c) * 4];
    std::vector<int> out;
    for (int k = 0; k < static_cast<int>(h[1]); ++k)
        out.push_back(static_cast<int>(texels[(static_cast<std::size_t>(indexBase) + static_cast<std::size_t>(h[0]) + k) * 4]));
    return out;
}

}  // namespace obscura::render
