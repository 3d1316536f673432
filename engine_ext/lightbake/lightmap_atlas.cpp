// See lightmap_atlas.h.
#include "lightbake/lightmap_atlas.h"

#include "lightbake/lightbake_shared.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace obscura::lightbake {

namespace {
constexpr int kBorder = LIGHTBAKE_CHART_BORDER;

// Two unit axes on the plane with normal n: s along the world axis the plane is least turned
// from, so walls run their s horizontally (the same choice for every face keeps charts predictable).
void planeAxes(const Vec3& n, Vec3& s, Vec3& t) {
    const Vec3 up = std::abs(n.y) < 0.9 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
    s = normalize(cross(up, n));
    t = cross(n, s);
}

// Shelf packing (charts sorted tallest first) into rows `width` wide; returns the height used.
int pack(std::vector<Chart>& charts, int width) {
    std::vector<std::size_t> order(charts.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return charts[a].h > charts[b].h; });
    int x = 0, y = 0, shelf = 0;
    for (std::size_t k : order) {
        Chart& c = charts[k];
        if (x + c.w > width) {
            y += shelf;
            x = 0;
            shelf = 0;
        }
        c.x = x;
        c.y = y;
        x += c.w;
        shelf = std::max(shelf, c.h);
    }
    return y + shelf;
}

// Charts at one texel size (positions not yet packed).
std::vector<Chart> makeCharts(const map::Level& level, double texel) {
    std::vector<Chart> charts;
    for (std::size_t b = 0; b < level.brushes.size(); ++b) {
        const auto& brush = level.brushes[b];
        for (std::size_t f = 0; f < brush.faces.size(); ++f) {
            const auto& face = brush.faces[f];
            if (!bakedFace(brush, face)) continue;
            Chart c;
            c.ref = {static_cast<int>(b), static_cast<int>(f)};
            c.normal = normalize(face.normal);
            planeAxes(c.normal, c.s, c.t);
            c.planeD = dot(c.normal, face.vertices[0].position);
            double sMax = -1e300, tMax = -1e300;
            c.sMin = c.tMin = 1e300;
            for (const auto& v : face.vertices) {
                const double ps = dot(v.position, c.s), pt = dot(v.position, c.t);
                c.sMin = std::min(c.sMin, ps);
                c.tMin = std::min(c.tMin, pt);
                sMax = std::max(sMax, ps);
                tMax = std::max(tMax, pt);
            }
            c.w = static_cast<int>(std::ceil((sMax - c.sMin) / texel)) + 2 * kBorder;
            c.h = static_cast<int>(std::ceil((tMax - c.tMin) / texel)) + 2 * kBorder;
            charts.push_back(c);
        }
    }
    return charts;
}
}  // namespace

bool bakedFace(const map::LevelBrush& brush, const map::LevelPolygon& face) {
    return brush.visible && !brush.mover && brush.liquid == map::LiquidKind::None && face.visible && !face.sky &&
           face.vertices.size() >= 3;
}

void Atlas::atlasCoord(const Chart& c, const Vec3& p, double& u, double& v) const {
    u = c.x + kBorder + (dot(p, c.s) - c.sMin) / texel;
    v = c.y + kBorder + (dot(p, c.t) - c.tMin) / texel;
}

Vec3 Atlas::texelCentre(const Chart& c, int i, int j) const {
    const double ps = c.sMin + (i + 0.5 - kBorder) * texel, pt = c.tMin + (j + 0.5 - kBorder) * texel;
    return c.normal * c.planeD + c.s * ps + c.t * pt;
}

void Atlas::bilinear(const std::vector<float>& values, int channels, const Chart& c, const Vec3& p, float* out) const {
    double u, v;
    atlasCoord(c, p, u, v);
    const double fu = u - 0.5, fv = v - 0.5;
    const int x0 = static_cast<int>(std::floor(fu)), y0 = static_cast<int>(std::floor(fv));
    const double ax = fu - x0, ay = fv - y0;
    for (int k = 0; k < channels; ++k) out[k] = 0;
    for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
            const int x = std::clamp(x0 + dx, c.x, c.x + c.w - 1), y = std::clamp(y0 + dy, c.y, c.y + c.h - 1);
            const double w = (dx ? ax : 1 - ax) * (dy ? ay : 1 - ay);
            const float* texel = &values[(static_cast<std::size_t>(y) * width + x) * channels];
            for (int k = 0; k < channels; ++k) out[k] += static_cast<float>(w * texel[k]);
        }
}

Atlas buildAtlas(const map::Level& level, double texel, std::string* note) {
    const double asked = texel;
    const double size = level.bounds.empty() ? 1.0 : length(level.bounds.max - level.bounds.min);
    for (;;) {
        // Every chart is at least (1 + 2 borders)^2 texels however coarse the texel: a level with
        // that many faces cannot be charted within the limit at all.
        if (texel > size) {
            std::ostringstream s;
            s << "the level's faces do not fit " << kMaxAtlasTexels
              << " lightmap texels at any texel size (lightbake/lightmap_atlas.h: kMaxAtlasTexels)";
            throw std::runtime_error(s.str());
        }
        Atlas atlas;
        atlas.texel = texel;
        atlas.charts = makeCharts(level, texel);
        std::size_t area = 0;
        int widest = 1;
        for (const auto& c : atlas.charts) {
            area += static_cast<std::size_t>(c.w) * static_cast<std::size_t>(c.h);
            widest = std::max(widest, c.w);
        }
        // A width near the square root of the charts' area, in multiples of 64, at least the widest chart.
        int width = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(area) * 1.1) / 64.0)) * 64;
        width = std::max({width, widest, 64});
        if (width <= kMaxAtlasWidth) {
            atlas.width = width;
            atlas.height = std::max(1, pack(atlas.charts, width));
            if (atlas.texels() <= kMaxAtlasTexels) {
                if (note && texel != asked) {
                    std::ostringstream s;
                    s << "the level's faces need more than " << kMaxAtlasTexels << " lightmap texels at " << asked
                      << " m a texel (lightbake/lightmap_atlas.h: kMaxAtlasTexels); baked at " << texel << " m";
                    *note = s.str();
                }
                return atlas;
            }
        }
        texel *= 1.25;
    }
}

}  // namespace obscura::lightbake
