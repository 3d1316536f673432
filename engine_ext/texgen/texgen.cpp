// Procedural level textures from texture names: see texgen.h. Every colour below is an sRGB
// albedo; the base values follow measured albedo charts for the material (red brick ~0.55/0.27/0.18,
// concrete ~0.55 grey, plaster ~0.7 warm white, ...), the multipliers are the per-texel variation.
#include "texgen/texgen.h"

#include "map/surface_rules.h"

#include "core/rng.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <memory>

namespace obscura::texgen {

namespace {

struct Colour {
    double r, g, b;
};
Colour operator*(const Colour& c, double k) { return {c.r * k, c.g * k, c.b * k}; }
Colour mix(const Colour& a, const Colour& b, double t) { return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t}; }

// Periodic value noise: a lattice of `cells` x `cells` random values that wraps around, so the
// texture tiles. Smoothstep-interpolated.
class PeriodicNoise {
public:
    PeriodicNoise(std::uint64_t seed, int cells) : cells_(cells), values_(static_cast<std::size_t>(cells * cells)) {
        Rng rng(seed);
        for (auto& v : values_) v = rng.uniform01();
    }
    // u, v in [0, 1): position in the tile.
    double at(double u, double v) const {
        const double x = u * cells_, y = v * cells_;
        const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
        const double fx = x - x0, fy = y - y0;
        const double sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
        const double a = lattice(x0, y0), b = lattice(x0 + 1, y0), c = lattice(x0, y0 + 1), d = lattice(x0 + 1, y0 + 1);
        return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
    }

private:
    double lattice(int x, int y) const {
        x = ((x % cells_) + cells_) % cells_;
        y = ((y % cells_) + cells_) % cells_;
        return values_[static_cast<std::size_t>(y * cells_ + x)];
    }
    int cells_;
    std::vector<float> values_;
};

// Fractal sum of periodic octaves (4, 8, 16, 32 cells...), normalised to 0..1. Gain 0.5 per
// octave (the classic 1/f fBm): each finer octave adds half the contrast, so detail never turns
// into per-texel noise that aliases.
class Fbm {
public:
    Fbm(std::uint64_t seed, int baseCells, int octaves) {
        for (int i = 0; i < octaves; ++i) octaves_.emplace_back(seed * 31 + static_cast<std::uint64_t>(i), baseCells << i);
    }
    double at(double u, double v) const {
        double sum = 0, amp = 1, norm = 0;
        for (const auto& o : octaves_) {
            sum += o.at(u, v) * amp;
            norm += amp;
            amp *= 0.5;
        }
        return sum / norm;
    }

private:
    std::vector<PeriodicNoise> octaves_;
};

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

bool has(const std::string& s, const char* k) { return s.find(k) != std::string::npos; }

// HSV -> RGB, all 0..1.
Colour hsv(double h, double s, double v) {
    h = std::fmod(h, 1.0) * 6.0;
    const int i = static_cast<int>(h);
    const double f = h - i, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    switch (i % 6) {
        case 0: return {v, t, p};
        case 1: return {q, v, p};
        case 2: return {p, v, t};
        case 3: return {p, q, v};
        case 4: return {t, p, v};
        default: return {v, p, q};
    }
}

// Distance (in tile units) to the nearest grid line of an n x m grid, offsetting odd rows by half
// a cell when `staggered` (brick bond). Returns the cell id through `cell`.
double mortar(double u, double v, int cols, int rows, bool staggered, int& cell) {
    const double y = v * rows;
    const int row = static_cast<int>(std::floor(y));
    double x = u * cols + (staggered && (row & 1) ? 0.5 : 0.0);
    const int col = static_cast<int>(std::floor(x));
    cell = (((row % rows) + rows) % rows) * 1000 + ((col % cols) + cols) % cols;
    const double fx = x - col, fy = y - row;
    return std::min({fx / cols, (1 - fx) / cols, fy / rows, (1 - fy) / rows});
}

using Shader = std::function<Colour(double u, double v)>;

Shader styleFor(const std::string& name, std::uint32_t seed) {
    // Large-scale blotches: 4 cells per tile (32 texels at 128) and 5 octaves down to 2 texels.
    auto fbm = std::make_shared<Fbm>(seed, 4, 5);
    // Fine grain: 16..64 cells per tile, a separate stream (golden-ratio constant) so it does not
    // correlate with the blotches.
    auto fine = std::make_shared<Fbm>(seed ^ 0x9e3779b9u, 16, 3);
    Rng rng(seed);
    // +-0.04 red shift per name, so two brick walls with different names are not identical.
    const double tint = rng.uniform(-0.04f, 0.04f);
    if (const map::ToolSurface tool = map::toolSurface(name); tool != map::ToolSurface::None) {
        // A tool texture, seen only in the editor (the game draws none of them): its own colour
        // with diagonal stripes, as editors show them (clip orange, trigger purple, hint cyan...).
        using T = map::ToolSurface;
        const Colour c = tool == T::Clip ? Colour{0.8, 0.45, 0.15} : tool == T::MonsterClip ? Colour{0.55, 0.35, 0.2}
                         : tool == T::Trigger ? Colour{0.6, 0.3, 0.7} : tool == T::Hint ? Colour{0.25, 0.7, 0.75}
                         : tool == T::Skip ? Colour{0.5, 0.5, 0.5} : tool == T::Origin ? Colour{0.3, 0.4, 0.8}
                                            : Colour{0.75, 0.7, 0.3};
        return [c](double u, double v) { return std::fmod((u + v) * 4.0, 1.0) < 0.5 ? c : c * 0.7; };
    }
    if (has(name, "sky")) {
        // Blue sky (0.42, 0.58, 0.82) with white clouds where the fBm exceeds 0.45 (about half
        // the sky), ramping over 0.4 of noise range so cloud edges stay soft.
        return [fbm](double u, double v) {
            const double c = fbm->at(u, v);
            return mix(Colour{0.42, 0.58, 0.82}, Colour{0.86, 0.9, 0.95}, std::clamp((c - 0.45) * 2.5, 0.0, 1.0));
        };
    }
    if (!name.empty() && name[0] == '*' && has(name, "tele")) {
        // A teleporter: Quake's *teleport is a sparkling field, not water: violet with white
        // where the fine noise peaks (about a fifth of the texels), so it never reads as a pool.
        return [fbm, fine](double u, double v) {
            const double spark = std::clamp((fine->at(u, v) - 0.55) * 4.0, 0.0, 1.0);
            return mix(Colour{0.3, 0.2, 0.6} * (0.7 + 0.6 * fbm->at(u, v)), Colour{0.9, 0.9, 0.98}, spark);
        };
    }
    if (!name.empty() && name[0] == '*') {  // liquids: base colour +-25 % by the fBm (ripples)
        const Colour base = has(name, "lava") ? Colour{0.75, 0.28, 0.06} : has(name, "slime") ? Colour{0.25, 0.5, 0.15}
                                                                                          : Colour{0.15, 0.32, 0.45};
        return [fbm, base](double u, double v) { return base * (0.75 + 0.5 * fbm->at(u, v)); };
    }
    if (has(name, "target")) {
        // A shooting target: a bullseye of 5 rings (red centre, alternating white and black) on a
        // white board, so hits read from 30 m; a little fBm grime so it is not flat.
        return [fine](double u, double v) {
            const double r = std::hypot(u - 0.5, v - 0.5) * 2.0;  // 0 at the centre, 1 at the edge
            const int ring = static_cast<int>(r * 5.0);
            Colour c = ring == 0 ? Colour{0.75, 0.08, 0.06} : ring >= 5 ? Colour{0.85, 0.84, 0.8}
                       : (ring & 1) ? Colour{0.08, 0.08, 0.08} : Colour{0.88, 0.87, 0.84};
            return c * (0.92 + 0.12 * fine->at(u, v));
        };
    }
    if (has(name, "barrel")) {
        // An oil drum: blue paint with two darker hoops, worn paler in patches.
        return [fbm, fine](double u, double v) {
            (void)u;
            const bool hoop = std::fabs(v - 0.33) < 0.025 || std::fabs(v - 0.67) < 0.025;
            const Colour paint = Colour{0.12, 0.24, 0.5} * (0.8 + 0.3 * fbm->at(u, v)) * (0.95 + 0.1 * fine->at(u, v));
            return hoop ? paint * 0.6 : paint;
        };
    }
    if (has(name, "light")) {
        // A light panel: a bright diffuser (0.8, not white: it is an albedo, the glow is the
        // light's job) inside a grey metal frame 8 % of the tile wide.
        return [fine](double u, double v) {
            int cell;
            const double d = mortar(u, v, 1, 1, false, cell);
            return d < 0.08 ? Colour{0.45, 0.45, 0.47} * (0.9 + 0.2 * fine->at(u, v)) : Colour{0.8, 0.8, 0.76};
        };
    }
    if (has(name, "brick") || has(name, "brk")) {
        // One tile is 2 m (64 texels at 32 units/m): 8 courses of 25 cm, 4 bricks of 50 cm a row,
        // a little larger than real bricks so they read at play distance.
        return [fbm, fine, seed, tint](double u, double v) {
            int cell;
            const double d = mortar(u, v, 4, 8, true, cell);
            Rng r(seed + static_cast<std::uint32_t>(cell) * 7919u);
            const double shade = 0.8 + 0.35 * r.uniform01();
            const Colour brick = Colour{0.55 + tint, 0.27, 0.18} * shade * (0.85 + 0.3 * fine->at(u, v));
            const Colour mortarC = Colour{0.62, 0.6, 0.55} * (0.9 + 0.2 * fbm->at(u, v));
            return d < 0.007 ? mortarC : brick;  // mortar joints ~2 texels wide at 128
        };
    }
    if (has(name, "tile")) {
        // 4 x 4 ceramic tiles, each +-6 % in brightness, with dark grout lines ~2 texels wide.
        return [fine, seed](double u, double v) {
            int cell;
            const double d = mortar(u, v, 4, 4, false, cell);
            Rng r(seed + static_cast<std::uint32_t>(cell) * 104729u);
            const Colour tile = Colour{0.72, 0.7, 0.66} * (0.9 + 0.12 * r.uniform01()) * (0.95 + 0.1 * fine->at(u, v));
            return d < 0.008 ? Colour{0.35, 0.34, 0.32} : tile;
        };
    }
    if (has(name, "metal") || has(name, "plate") || has(name, "tech")) {
        // Steel floor plates (grey 0.46..0.5): 2 x 2 plates with dark seams, a diamond tread of 16
        // lozenges per plate edge (8 texels each at 128: coarse enough not to alias).
        return [fbm, fine](double u, double v) {
            int cell;
            const double d = mortar(u, v, 2, 2, false, cell);
            // Diamond tread: a raised lozenge pattern.
            const double tread = std::fabs(std::sin((u + v) * 3.14159265 * 16)) * std::fabs(std::sin((u - v) * 3.14159265 * 16));
            Colour c = Colour{0.46, 0.48, 0.5} * (0.85 + 0.2 * fbm->at(u, v) + 0.1 * fine->at(u, v));
            if (tread > 0.85) c = c * 1.18;
            return d < 0.006 ? c * 0.55 : c;
        };
    }
    if (has(name, "wood") || has(name, "crate") || has(name, "plank")) {
        // Four planks per tile with dark gaps; grain = 12 warped sine bands per plank, a random
        // phase and brightness per plank. Colours between dark and light pine-brown.
        return [fbm, fine, seed](double u, double v) {
            int cell;
            const double d = mortar(u, v, 1, 4, false, cell);
            Rng r(seed + static_cast<std::uint32_t>(cell) * 15485863u);
            const double grain = 0.5 + 0.5 * std::sin((u * 2 + fbm->at(u, v) * 1.5) * 3.14159265 * 12 + r.uniform01() * 6);
            const Colour c = mix(Colour{0.42, 0.27, 0.14}, Colour{0.62, 0.44, 0.25}, grain * 0.6 + 0.4 * fine->at(u, v));
            return d < 0.01 ? c * 0.45 : c * (0.9 + 0.2 * r.uniform01());
        };
    }
    if (has(name, "stone") || has(name, "rock") || has(name, "cobble")) {
        // 3 x 3 staggered flagstones, each +-15 % in brightness, mottled by the fBm, dark joints.
        return [fbm, fine, seed](double u, double v) {
            int cell;
            const double d = mortar(u, v, 3, 3, true, cell);
            Rng r(seed + static_cast<std::uint32_t>(cell) * 6151u);
            const Colour c = Colour{0.5, 0.49, 0.46} * (0.8 + 0.3 * r.uniform01()) * (0.8 + 0.35 * fbm->at(u, v) + 0.1 * fine->at(u, v));
            return d < 0.01 ? Colour{0.3, 0.29, 0.27} : c;
        };
    }
    if (has(name, "grass") || has(name, "ground") || has(name, "dirt")) {
        // Olive green between dry and fresh grass; no structure, so it tiles without a visible grid.
        return [fbm, fine](double u, double v) {
            return mix(Colour{0.32, 0.36, 0.16}, Colour{0.44, 0.52, 0.22}, 0.6 * fbm->at(u, v) + 0.4 * fine->at(u, v));
        };
    }
    if (has(name, "concrete") || has(name, "cement")) {
        return [fbm, fine](double u, double v) {
            int cell;
            const double d = mortar(u, v, 1, 1, false, cell);  // a form-work seam per tile
            // Grey concrete, 0.82..1.19 by the stains and grain.
            const Colour c = Colour{0.56, 0.55, 0.52} * (0.82 + 0.25 * fbm->at(u, v) + 0.12 * fine->at(u, v));
            return d < 0.004 ? c * 0.7 : c;
        };
    }
    if (has(name, "plaster") || has(name, "wall")) {
        // Warm off-white plaster, only +-8 % variation: a plain wall (the sign test reads it).
        return [fbm, fine, tint](double u, double v) {
            return Colour{0.74 + tint, 0.7, 0.62} * (0.9 + 0.12 * fbm->at(u, v) + 0.05 * fine->at(u, v));
        };
    }
    // Unknown name: a muted colour from its hash (saturation 0.25..0.5, value 0.45..0.7: not
    // garish, not dark), faint noise (+-10 %) and a grid every quarter tile, 20 % darker, so the
    // texture's scale reads on a surface.
    const double hue = (seed & 0xffff) / 65536.0;
    const double sat = 0.25 + 0.25 * ((seed >> 16) & 0xff) / 255.0;
    const double val = 0.45 + 0.25 * ((seed >> 24) & 0xff) / 255.0;
    const Colour base = hsv(hue, sat, val);
    return [fbm, base](double u, double v) {
        int cell;
        const double d = mortar(u, v, 4, 4, false, cell);
        const Colour c = base * (0.88 + 0.2 * fbm->at(u, v));
        return d < 0.004 ? c * 0.8 : c;
    };
}

std::uint8_t toByte(double x) { return static_cast<std::uint8_t>(std::lround(std::clamp(x, 0.0, 1.0) * 255.0)); }

// Fence textures (`{` names, map/surface_rules.h): a welded grille, 8 x 8 square holes a tile (a
// 64-unit Quake texture spans 2 m: 25 cm cells) between bars 3/8 of a cell wide (6 of 16 texels at
// 128 px). Bars cover 1 - 0.625^2 = 61 % of the tile, so the mipmapped alpha stays above the 0.5
// cut-off far away: the fence does not vanish at a distance. Alpha 255 on the bars, 0 in the holes.
constexpr int kFenceCells = 8;
constexpr double kFenceBar = 0.375;
bool fenceBar(double u, double v) {
    const double fu = u * kFenceCells - std::floor(u * kFenceCells), fv = v * kFenceCells - std::floor(v * kFenceCells);
    const double h = kFenceBar / 2;
    return fu < h || fu > 1 - h || fv < h || fv > 1 - h;
}

}  // namespace

std::uint32_t nameHash(const std::string& name) {
    std::uint32_t h = 2166136261u;
    for (unsigned char c : lower(name)) {
        h ^= c;
        h *= 16777619u;
    }
    return h;
}

Image generateTexture(const std::string& textureName, int size) {
    if (size < kMinSize || size > kMaxSize)
        throw TexgenError("texgen: texture '" + textureName + "': size " + std::to_string(size) + " outside " +
                          std::to_string(kMinSize) + ".." + std::to_string(kMaxSize));
    const std::string name = lower(textureName);
    const std::uint32_t seed = nameHash(name);
    const Shader shade = styleFor(name, seed);
    const bool fence = map::isFenceTexture(name);
    Image img;
    img.width = img.height = size;
    img.rgba.resize(static_cast<std::size_t>(size * size * 4));
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            // Sample at texel centres; the pattern functions are periodic on [0, 1).
            const Colour c = shade((x + 0.5) / size, (y + 0.5) / size);
            std::uint8_t* p = &img.rgba[static_cast<std::size_t>((y * size + x) * 4)];
            p[0] = toByte(c.r);
            p[1] = toByte(c.g);
            p[2] = toByte(c.b);
            p[3] = fence && !fenceBar((x + 0.5) / size, (y + 0.5) / size) ? 0 : 255;
        }
    return img;
}

}  // namespace obscura::texgen
