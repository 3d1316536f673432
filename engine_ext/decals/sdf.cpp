// See sdf.h.
#include "decals/sdf.h"

#include "core/image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace obscura::decals {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kFar = 1e20;  // "no feature here" (finite: the envelope's arithmetic stays exact)

// One row or column: d[q] = min_p (q - p)^2 + f[p], the lower envelope of the parabolas rooted at
// each p (Felzenszwalb & Huttenlocher, section 3). v: the parabolas kept, z: where each takes over.
void edt1d(const double* f, int n, double* d, int* v, double* z) {
    int k = 0;
    v[0] = 0;
    z[0] = -kFar * 10;
    z[1] = kFar * 10;
    auto meet = [&](int q, int p) { return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * q - 2.0 * p); };
    for (int q = 1; q < n; ++q) {
        double s = meet(q, v[k]);
        while (s <= z[k]) s = meet(q, v[--k]);  // z[0] is below any meeting point: stops at k = 0
        ++k;
        v[k] = q;
        z[k] = s;
        z[k + 1] = kFar * 10;
    }
    k = 0;
    for (int q = 0; q < n; ++q) {
        while (z[k + 1] < q) ++k;
        const double dq = q - v[k];
        d[q] = dq * dq + f[v[k]];
    }
}

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

struct Segment {
    Point a, b;
    int colour = 7;  // bits: 1 red, 2 green, 4 blue
};

// The distance from p to the segment, the parameter of the closest point (unclamped) and the signed
// perpendicular distance to the segment's line (> 0 on its left).
struct SegmentDistance {
    double distance, t, perpendicular, orthogonality;
};
SegmentDistance segmentDistance(const Segment& s, double px, double py) {
    const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    const double len2 = std::max(dx * dx + dy * dy, 1e-30);
    const double t = ((px - s.a.x) * dx + (py - s.a.y) * dy) / len2;
    const double tc = std::clamp(t, 0.0, 1.0);
    const double cx = s.a.x + tc * dx - px, cy = s.a.y + tc * dy - py;
    const double dist = std::sqrt(cx * cx + cy * cy);
    const double len = std::sqrt(len2);
    const double perp = cross(dx, dy, px - s.a.x, py - s.a.y) / len;
    const double orth = dist > 0 ? std::fabs(cross(dx / len, dy / len, -cx / dist, -cy / dist)) : 1.0;
    return {dist, t, perp, orth};
}

// Chlumský's simple edge colouring: corners where the outline turns by more than ~8 degrees; the
// runs of edges between corners alternate among cyan, magenta and yellow so that the two runs at a
// corner share exactly one channel. A smooth contour is white; one with one corner is cut in three.
std::vector<Segment> colourContour(const std::vector<Point>& c) {
    const int n = static_cast<int>(c.size());
    std::vector<Segment> segs;
    if (n < 3) return segs;
    for (int i = 0; i < n; ++i) segs.push_back({c[i], c[(i + 1) % n], 7});
    auto dir = [&](int i) {
        const Segment& s = segs[(i + n) % n];
        const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y, l = std::max(std::hypot(dx, dy), 1e-30);
        return Point{dx / l, dy / l};
    };
    const double crossThreshold = std::sin(3.0);
    std::vector<int> corners;  // edge i starts at a corner
    for (int i = 0; i < n; ++i) {
        const Point a = dir(i - 1), b = dir(i);
        if (a.x * b.x + a.y * b.y <= 0 || std::fabs(cross(a.x, a.y, b.x, b.y)) > crossThreshold) corners.push_back(i);
    }
    if (corners.empty()) return segs;
    if (corners.size() == 1) {
        const int colours[3] = {5, 7, 3};
        for (int k = 0; k < n; ++k) segs[(corners[0] + k) % n].colour = colours[std::min(2, 3 * k / n)];
        return segs;
    }
    const int cycle[3] = {6, 5, 3};  // cyan, magenta, yellow
    const int runs = static_cast<int>(corners.size());
    for (int r = 0; r < runs; ++r) {
        int colour = cycle[r % 3];
        if (r == runs - 1 && runs % 3 == 1) colour = cycle[1];  // neither the first run's nor the previous one's
        for (int i = corners[r]; i != corners[(r + 1) % runs]; i = (i + 1) % n) segs[i].colour = colour;
    }
    return segs;
}

double signedArea(const Shape& shape) {
    double a = 0;
    for (const auto& c : shape.contours)
        for (std::size_t i = 0; i < c.size(); ++i) {
            const Point& p = c[i];
            const Point& q = c[(i + 1) % c.size()];
            a += p.x * q.y - q.x * p.y;
        }
    return 0.5 * a;
}

std::uint32_t be32(const unsigned char* b) {
    return (std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) | (std::uint32_t(b[2]) << 8) | b[3];
}
}  // namespace

float Field::bilinear(double x, double y) const {
    const double fx = x - 0.5, fy = y - 0.5;
    const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
    const double tx = fx - x0, ty = fy - y0;
    auto tap = [&](int xi, int yi) { return at(std::clamp(xi, 0, width - 1), std::clamp(yi, 0, height - 1)); };
    const double top = tap(x0, y0) * (1 - tx) + tap(x0 + 1, y0) * tx;
    const double bottom = tap(x0, y0 + 1) * (1 - tx) + tap(x0 + 1, y0 + 1) * tx;
    return static_cast<float>(top * (1 - ty) + bottom * ty);
}

std::vector<float> squaredEdt(const std::vector<std::uint8_t>& feature, int width, int height) {
    const int n = std::max(width, height);
    std::vector<double> grid(static_cast<std::size_t>(width) * height), f(n), d(n), z(n + 1);
    std::vector<int> v(n);
    for (std::size_t i = 0; i < grid.size(); ++i) grid[i] = feature[i] ? 0.0 : kFar;
    for (int x = 0; x < width; ++x) {  // columns
        for (int y = 0; y < height; ++y) f[y] = grid[static_cast<std::size_t>(y) * width + x];
        edt1d(f.data(), height, d.data(), v.data(), z.data());
        for (int y = 0; y < height; ++y) grid[static_cast<std::size_t>(y) * width + x] = d[y];
    }
    std::vector<float> out(grid.size());
    for (int y = 0; y < height; ++y) {  // rows
        double* row = grid.data() + static_cast<std::size_t>(y) * width;
        edt1d(row, width, d.data(), v.data(), z.data());
        for (int x = 0; x < width; ++x) out[static_cast<std::size_t>(y) * width + x] = static_cast<float>(d[x]);
    }
    return out;
}

Field signedDistance(const Mask& mask) {
    std::vector<std::uint8_t> outside(mask.inside.size());
    for (std::size_t i = 0; i < outside.size(); ++i) outside[i] = mask.inside[i] ? 0 : 1;
    const std::vector<float> toInside = squaredEdt(mask.inside, mask.width, mask.height);
    const std::vector<float> toOutside = squaredEdt(outside, mask.width, mask.height);
    Field f{mask.width, mask.height, std::vector<float>(mask.inside.size())};
    const float cap = 2.0f * (mask.width + mask.height);  // an all-inside or all-outside mask
    for (std::size_t i = 0; i < f.v.size(); ++i)
        f.v[i] = mask.inside[i] ? std::min(cap, std::sqrt(toOutside[i]) - 0.5f) : -std::min(cap, std::sqrt(toInside[i]) - 0.5f);
    return f;
}

Mask maskFromPng(const std::string& path) {
    {   // The size from the header, before anything is decoded.
        std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
        if (!file) throw BakeError(path + ": cannot open the mask");
        unsigned char head[24];
        static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
        if (std::fread(head, 1, 24, file.get()) != 24 || !std::equal(sig, sig + 8, head) ||
            std::string(reinterpret_cast<char*>(head + 12), 4) != "IHDR")
            throw BakeError(path + ": the mask is not a PNG file");
        const std::uint32_t w = be32(head + 16), h = be32(head + 20);
        if (w == 0 || h == 0 || w > kMaxMaskEdge || h > kMaxMaskEdge || (long long)w * h > kMaxMaskPixels)
            throw BakeError(path + ": the mask is " + std::to_string(w) + " x " + std::to_string(h) +
                            " pixels; the baker takes at most " + std::to_string(kMaxMaskEdge) + " a side and " +
                            std::to_string(kMaxMaskPixels) + " in all");
    }
    Image im;
    try {
        im = readPng(path);
    } catch (const ImageError& e) {
        throw BakeError(e.what());
    }
    bool alphaVaries = false;
    for (std::size_t i = 3; i < im.rgba.size(); i += 4) alphaVaries |= im.rgba[i] != im.rgba[3];
    Mask m{im.width, im.height, std::vector<std::uint8_t>(static_cast<std::size_t>(im.width) * im.height)};
    for (std::size_t i = 0; i < m.inside.size(); ++i) {
        const std::uint8_t* p = &im.rgba[i * 4];
        const int value = alphaVaries ? p[3] : (p[0] * 299 + p[1] * 587 + p[2] * 114) / 1000;
        m.inside[i] = value >= 128;
    }
    return m;
}

Mask rasterize(const Shape& shape, int size) {
    if (size <= 0 || size > kMaxMaskEdge) throw BakeError("rasterize: size " + std::to_string(size) + " out of range");
    return rasterize(shape, size, size, size);
}

Mask rasterize(const Shape& shape, int width, int height, double pixelsPerUnit) {
    if (width <= 0 || height <= 0 || width > kMaxMaskEdge || height > kMaxMaskEdge)
        throw BakeError("rasterize: " + std::to_string(width) + " x " + std::to_string(height) + " out of range");
    if (!(pixelsPerUnit > 0) || !std::isfinite(pixelsPerUnit)) throw BakeError("rasterize: the scale must be positive");
    const double size = pixelsPerUnit;  // the square's formulas, with its size as the scale
    Mask m{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height)};
    struct Crossing {
        double x;
        int winding;
    };
    std::vector<Crossing> xs;
    for (int y = 0; y < height; ++y) {
        const double yc = (y + 0.5) / size;
        xs.clear();
        for (const auto& c : shape.contours)
            for (std::size_t i = 0; i < c.size(); ++i) {
                const Point& a = c[i];
                const Point& b = c[(i + 1) % c.size()];
                if (a.y == b.y) continue;
                const bool down = b.y > a.y;
                const double lo = down ? a.y : b.y, hi = down ? b.y : a.y;
                if (yc < lo || yc >= hi) continue;
                xs.push_back({a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y), down ? 1 : -1});
            }
        std::sort(xs.begin(), xs.end(), [](const Crossing& p, const Crossing& q) { return p.x < q.x; });
        int winding = 0;
        for (std::size_t k = 0; k < xs.size(); ++k) {
            winding += xs[k].winding;
            if (winding == 0 || k + 1 >= xs.size()) continue;
            // Pixels whose centres lie in [xs[k], xs[k+1]).
            const int x0 = std::max(0, static_cast<int>(std::ceil(xs[k].x * size - 0.5)));
            const int x1 = std::min(width - 1, static_cast<int>(std::ceil(xs[k + 1].x * size - 0.5)) - 1);
            for (int x = x0; x <= x1; ++x) m.inside[static_cast<std::size_t>(y) * width + x] = 1;
        }
    }
    return m;
}

Shape circleShape(double cx, double cy, double r, int segments) {
    Shape s;
    s.contours.emplace_back();
    for (int i = 0; i < segments; ++i) {
        const double a = 2 * kPi * i / segments;
        s.contours.back().push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    }
    return s;
}

Shape squareShape(double cx, double cy, double half, double degrees) {
    const double a = degrees * kPi / 180, c = std::cos(a), s = std::sin(a);
    Shape sh;
    sh.contours.emplace_back();
    const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& k : corners)
        sh.contours.back().push_back({cx + half * (k[0] * c - k[1] * s), cy + half * (k[0] * s + k[1] * c)});
    return sh;
}

Shape ringShape(double cx, double cy, double outer, double inner, int segments) {
    Shape s = circleShape(cx, cy, outer, segments);
    Shape hole = circleShape(cx, cy, inner, segments);
    std::reverse(hole.contours[0].begin(), hole.contours[0].end());
    s.contours.push_back(hole.contours[0]);
    return s;
}

Shape starShape(double cx, double cy, double outer, double inner, int points) {
    Shape s;
    s.contours.emplace_back();
    for (int i = 0; i < 2 * points; ++i) {
        const double a = kPi * i / points - kPi / 2, r = i % 2 ? inner : outer;
        s.contours.back().push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    }
    return s;
}

Field downsampleSdf(const Field& hi, int size) {
    if (size <= 0) throw BakeError("downsampleSdf: size must be positive");
    const double scale = static_cast<double>(hi.width) / size;
    Field f{size, size, std::vector<float>(static_cast<std::size_t>(size) * size)};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            f.v[static_cast<std::size_t>(y) * size + x] =
                static_cast<float>(hi.bilinear((x + 0.5) * scale, (y + 0.5) * scale) / scale);
    return f;
}

Field coverage(const Mask& mask, int size) {
    if (size <= 0 || mask.width % size || mask.height % size)
        throw BakeError("coverage: the mask's size is not a multiple of " + std::to_string(size));
    const int fx = mask.width / size, fy = mask.height / size;
    Field f{size, size, std::vector<float>(static_cast<std::size_t>(size) * size)};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            int n = 0;
            for (int j = 0; j < fy; ++j)
                for (int i = 0; i < fx; ++i) n += mask.at(x * fx + i, y * fy + j);
            f.v[static_cast<std::size_t>(y) * size + x] = static_cast<float>(n) / (fx * fy);
        }
    return f;
}

Msdf multiChannel(const Shape& shape, int size) {
    if (size <= 0) throw BakeError("multiChannel: size must be positive");
    std::vector<Segment> segs;
    for (const auto& c : shape.contours) {
        auto s = colourContour(c);
        segs.insert(segs.end(), s.begin(), s.end());
    }
    if (segs.empty()) throw BakeError("multiChannel: the shape has no outline");
    const double orientation = signedArea(shape) >= 0 ? 1.0 : -1.0;  // inside on the left of every edge
    Msdf m;
    for (Field* f : {&m.r, &m.g, &m.b}) *f = Field{size, size, std::vector<float>(static_cast<std::size_t>(size) * size)};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double px = (x + 0.5) / size, py = (y + 0.5) / size;
            float* out[3] = {&m.r.v[static_cast<std::size_t>(y) * size + x], &m.g.v[static_cast<std::size_t>(y) * size + x],
                             &m.b.v[static_cast<std::size_t>(y) * size + x]};
            for (int ch = 0; ch < 3; ++ch) {
                const Segment* best = nullptr;
                SegmentDistance bd{1e30, 0, 0, 0};
                for (const Segment& s : segs) {
                    if (!(s.colour & (1 << ch))) continue;
                    const SegmentDistance d = segmentDistance(s, px, py);
                    // Nearest first; at a shared vertex (equal distances) the edge that faces the point.
                    if (d.distance < bd.distance - 1e-12 ||
                        (std::fabs(d.distance - bd.distance) <= 1e-12 && d.orthogonality > bd.orthogonality)) {
                        bd = d;
                        best = &s;
                    }
                }
                if (!best) {
                    *out[ch] = 0;
                    continue;
                }
                // Inside the segment's span: the distance with its sign; beyond an end: the
                // pseudo-distance to the extended edge (what makes the median's corner sharp).
                double value;
                if (bd.t >= 0 && bd.t <= 1) value = (bd.perpendicular >= 0 ? 1 : -1) * bd.distance;
                else value = std::fabs(bd.perpendicular) <= bd.distance ? bd.perpendicular : (bd.perpendicular >= 0 ? 1 : -1) * bd.distance;
                *out[ch] = static_cast<float>(orientation * value * size);
            }
        }
    return m;
}

int correctClashes(Msdf& m, const Field& sdf, double tolerance) {
    const int w = sdf.width, h = sdf.height;
    auto at = [w](int x, int y) { return static_cast<std::size_t>(y) * w + x; };
    auto median3 = [](double r, double g, double b) { return std::max(std::min(r, g), std::min(std::max(r, g), b)); };
    std::vector<std::uint8_t> bad(static_cast<std::size_t>(w) * h);
    // 1. Texels whose own median is off the true distance (and their 4 neighbours).
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (std::fabs(median3(m.r.v[at(x, y)], m.g.v[at(x, y)], m.b.v[at(x, y)]) - sdf.v[at(x, y)]) > tolerance) {
                bad[at(x, y)] = 1;
                if (x > 0) bad[at(x - 1, y)] = 1;
                if (x + 1 < w) bad[at(x + 1, y)] = 1;
                if (y > 0) bad[at(x, y - 1)] = 1;
                if (y + 1 < h) bad[at(x, y + 1)] = 1;
            }
    // 2. Clashes between texels each right on its own: bilinear filtering blends the channels, and
    // the median of a blend is not the blend of the medians, so a false contour can appear between
    // two or four texels (Chlumský's interpolation artefacts). Checked at the quarter, half and
    // three-quarter points of every horizontal, vertical and diagonal pair within a 2x2 cell (the
    // diagonals' midpoints are the cell's centre): where the median there is more than
    // `tolerance` from the true distance blended the same way and on the other side of the edge,
    // every texel of the pair falls back.
    auto blendClash = [&](std::size_t a, std::size_t b) {
        for (double t : {0.25, 0.5, 0.75}) {
            const double mr = m.r.v[a] + (m.r.v[b] - m.r.v[a]) * t, mg = m.g.v[a] + (m.g.v[b] - m.g.v[a]) * t,
                         mb = m.b.v[a] + (m.b.v[b] - m.b.v[a]) * t;
            const double md = median3(mr, mg, mb), sd = sdf.v[a] + (sdf.v[b] - sdf.v[a]) * t;
            if ((md > 0) != (sd > 0) && std::fabs(md - sd) > tolerance) return true;
        }
        return false;
    };
    std::vector<std::uint8_t> clash(bad.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t p = at(x, y);
            const int pairs[4][2] = {{1, 0}, {0, 1}, {1, 1}, {-1, 1}};
            for (const auto& d : pairs) {
                const int qx = x + d[0], qy = y + d[1];
                if (qx < 0 || qx >= w || qy >= h) continue;
                if (blendClash(p, at(qx, qy))) clash[p] = clash[at(qx, qy)] = 1;
            }
        }
    int n = 0;
    for (std::size_t i = 0; i < bad.size(); ++i)
        if (bad[i] || clash[i]) {
            m.r.v[i] = m.g.v[i] = m.b.v[i] = sdf.v[i];
            ++n;
        }
    return n;
}

std::uint8_t encode(double distance, double range) {
    const double v = 0.5 + distance / (2 * range);
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

double decode(std::uint8_t value, double range) { return (value / 255.0 - 0.5) * 2 * range; }

EdgeError edgeError(int lowResSize, int magnification, double threshold,
                    const std::function<double(double, double)>& lowRes,
                    const std::function<double(double, double)>& trueDistance,
                    const std::function<bool(double, double)>& where) {
    const int n = lowResSize * magnification;
    std::vector<double> s(static_cast<std::size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            s[static_cast<std::size_t>(j) * n + i] = lowRes((i + 0.5) / magnification, (j + 0.5) / magnification) - threshold;
    EdgeError e;
    double sum = 0;
    auto visit = [&](double a, double b, double u0, double v0, double du, double dv) {
        if ((a > 0) == (b > 0)) return;
        const double t = a / (a - b);
        const double u = u0 + t * du, v = v0 + t * dv;
        if (where && !where(u, v)) return;
        const double err = std::fabs(trueDistance(u, v)) * n;
        sum += err;
        e.max = std::max(e.max, err);
        ++e.crossings;
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            visit(s[static_cast<std::size_t>(j) * n + i], s[static_cast<std::size_t>(j) * n + i + 1], (i + 0.5) / n,
                  (j + 0.5) / n, 1.0 / n, 0);
            visit(s[static_cast<std::size_t>(i) * n + j], s[static_cast<std::size_t>(i + 1) * n + j], (j + 0.5) / n,
                  (i + 0.5) / n, 0, 1.0 / n);
        }
    e.mean = e.crossings ? sum / e.crossings : 0;
    return e;
}

}  // namespace obscura::decals
