// SmokeVolume's read side: accessors, sampling, transmittance, texture export, validation.
#include <algorithm>
#include <cstring>
#include <cmath>
#include <sstream>

#include "smoke/smoke_volume.h"
#include "smoke/smoke_volume_impl.h"
#include "smoke/thread_pool.h"
#include "smoke/voxelize.h"

namespace obscura::smoke {

double SmokeVolume::age() const { return impl_->state.age; }
bool SmokeVolume::emitting() const { return impl_->state.age < impl_->settings.emitTime; }
bool SmokeVolume::finished() const { return impl_->state.age >= impl_->settings.lifetime; }
const GridInfo& SmokeVolume::grid() const { return impl_->state.grid; }
const SmokeSettings& SmokeVolume::settings() const { return impl_->settings; }
const SmokeStats& SmokeVolume::stats() const { return impl_->state.stats; }
Vec3 SmokeVolume::centre() const { return impl_->state.centre; }
int SmokeVolume::threads() const { return impl_->pool->threads(); }
const SmokeState& SmokeVolume::state() const { return impl_->state; }
SmokeState& SmokeVolume::mutableState() { return impl_->state; }
const std::vector<float>& SmokeVolume::transmittance() const { return impl_->transmittance; }

float SmokeVolume::densityAt(int i, int j, int k) const {
    const GridInfo& g = impl_->state.grid;
    return g.contains(i, j, k) ? impl_->state.density[g.index(i, j, k)] : 0.f;
}
bool SmokeVolume::solidAt(int i, int j, int k) const {
    const GridInfo& g = impl_->state.grid;
    return !g.contains(i, j, k) || impl_->state.cellClass[g.index(i, j, k)] == kSolid;
}
bool SmokeVolume::voxelSolidAt(int i, int j, int k) const {
    const GridInfo& g = impl_->state.grid;
    return !g.contains(i, j, k) || impl_->state.voxelSolid[g.index(i, j, k)] != 0;
}

double SmokeVolume::sampleDensity(const Vec3& world) const {
    const SmokeState& s = impl_->state;
    const Vec3 c = s.grid.toCellCoords(world);
    if (!(c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x <= s.grid.nx - 1 && c.y <= s.grid.ny - 1 && c.z <= s.grid.nz - 1))
        return 0.0;
    return kernels::sample(s.density.data(), s.dims, static_cast<float>(c.x), static_cast<float>(c.y),
                           static_cast<float>(c.z));
}

double SmokeVolume::opticalDepth(const Vec3& from, const Vec3& to) const {
    const double len = length(to - from);
    if (!(len > 0) || !std::isfinite(len)) return 0.0;
    const double step = 0.5 * impl_->state.grid.cellSize;  // half a cell: no cell skipped
    const int n = std::min(100000, static_cast<int>(std::ceil(len / step)));
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += sampleDensity(from + (to - from) * ((i + 0.5) / n));
    return sum * len / n;
}

double SmokeVolume::totalDensity() const {
    const SmokeState& s = impl_->state;
    double sum = 0;  // one fixed order
    for (float d : s.density) sum += d;
    const double h = s.grid.cellSize;
    return sum * h * h * h;
}

double SmokeVolume::maxDivergence() const {
    const SmokeState& s = impl_->state;
    const auto& d = s.dims;
    const float invH = 1.f / static_cast<float>(s.grid.cellSize);
    const float emit = s.projectedSource;  // the source the last projection solved for
    double worst = 0;
    for (int k = 1; k < d.nz - 1; ++k)
        for (int j = 1; j < d.ny - 1; ++j)
            for (int i = 1; i < d.nx - 1; ++i) {
                const std::ptrdiff_t c = d.sy * j + d.sz * k + i;
                if (s.cellClass[static_cast<std::size_t>(c)] != kFluid) continue;
                const float div = kernels::divergenceAt(s.u.data(), s.v.data(), s.w.data(), c, d, invH);
                worst = std::max(worst, static_cast<double>(std::fabs(div - s.source[static_cast<std::size_t>(c)] * emit)));
            }
    return worst;
}

namespace {

// exp(-x) for x >= 0 without libm: 2^(-x log2 e) as 2^k (exponent bits) times a degree-6
// Taylor polynomial of 2^f on [0, 1): relative error < 2e-5, far below the 8-bit texture's
// step; plain float operations, so it vectorises and gives the same bits everywhere.
float expNeg(float x) {
    x = kernels::clampf(x, 0.f, 87.f);  // e^-87 ~ 1.6e-38: the smallest normal float
    const float y = -x * 1.44269504f;    // log2(e)
    int k = static_cast<int>(y);         // trunc toward 0; y <= 0 so floor is k or k - 1
    k -= static_cast<float>(k) > y ? 1 : 0;
    const float f = y - static_cast<float>(k);  // [0, 1)
    const float t = f * 0.693147181f;           // ln 2
    const float p = 1.f + t * (1.f + t * (0.5f + t * (0.166666667f + t * (0.0416666667f + t * (0.00833333333f + t * 0.00138888889f)))));
    const std::uint32_t bits = static_cast<std::uint32_t>(k + 127) << 23;
    float scale;
    std::memcpy(&scale, &bits, 4);
    return p * scale;
}

// T[i] = e^-tau[i] for every cell, on the pool (T may be tau: each cell reads only itself).
void transmittanceOf(ThreadPool& pool, const std::vector<float>& tau, std::vector<float>& T) {
    const std::size_t cells = tau.size();
    pool.parallelFor(64, [&](int c0, int c1) {
        const std::size_t e = cells * static_cast<std::size_t>(c1) / 64;
        for (std::size_t i = cells * static_cast<std::size_t>(c0) / 64; i < e; ++i) T[i] = expNeg(tau[i]);
    });
}

}  // namespace

void SmokeVolume::computeTransmittance(const Vec3& towardLight) {
    const SmokeState& s = impl_->state;
    std::vector<float>& T = impl_->transmittance;
    const Vec3 L = normalize(towardLight);
    if (dot(L, L) == 0 || !std::isfinite(L.x + L.y + L.z)) {
        std::fill(T.begin(), T.end(), 1.f);
        return;
    }
    // Optical depth swept slice by slice along the dominant axis a, from the light's side: each
    // cell adds half its own density and half the density one slice toward the light (bilinear
    // at the light direction's constant offset) to that point's depth. Cells of one slice are
    // independent: the slice's rows go to the thread pool. Built cells (walls, roofs, models'
    // meshes) are opaque: each adds kOpaque to the depth, so the smoke under a roof or behind a
    // wall is in its shadow (without it the sun lit smoke in a roofed corridor through the roof,
    // and the slices' bilinear steps showed as bright blocks).
    const double comp[3] = {L.x, L.y, L.z};
    int a = 0;
    for (int x = 1; x < 3; ++x)
        if (std::fabs(comp[x]) > std::fabs(comp[a])) a = x;
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const int n[3] = {s.grid.nx, s.grid.ny, s.grid.nz};
    const std::ptrdiff_t stride[3] = {1, s.dims.sy, s.dims.sz};
    const int dirA = comp[a] > 0 ? 1 : -1;  // the previous slice (toward the light) is at +dirA
    const double ob = comp[b] / std::fabs(comp[a]), oc = comp[c] / std::fabs(comp[a]);  // in [-1, 1]
    const int ib = static_cast<int>(std::floor(ob)), ic = static_cast<int>(std::floor(oc));
    const float fb = static_cast<float>(ob - ib), fc = static_cast<float>(oc - ic);
    const float halfStep = static_cast<float>(impl_->settings.shadowSigma * s.grid.cellSize / std::fabs(comp[a])) * 0.5f;
    std::vector<float>& tau = impl_->opticalDepth;
    tau.assign(s.grid.cells(), 0.f);
    const float* den = s.density.data();
    const std::uint8_t* built = s.voxelSolid.data();
    constexpr float kOpaque = 12.f;  // optical depth of a built cell: e^-12, no light gets through
    auto at = [&](int sa, int xb, int yc) {
        return static_cast<std::size_t>(sa * stride[a] + xb * stride[b] + yc * stride[c]);
    };
    const int first = dirA > 0 ? n[a] - 1 : 0;
    // The inner loop runs along whichever of the slice's axes is contiguous in memory (x, or y
    // when x is the sweep's axis): with the sun high (a = y) the other order stepped a whole
    // plane (16 KB at 64^3) from one cell to the next: 2.7-4.0 ms a 64^3 sweep of the sun at
    // (0.3, 1, 0.2) against 1.0-1.1 ms in this order (alternating runs of the two builds, 10
    // sweeps each, fastest). Each cell of a slice reads only the slice before, so the order
    // changes no value (a hash of the sun's and the lamps' maps over six directions: the same).
    const bool bInner = stride[b] < stride[c];
    const int outerN = bInner ? n[c] : n[b], innerN = bInner ? n[b] : n[c];
    for (int step = 1; step < n[a]; ++step) {
        const int sa = first - dirA * step, prev = sa + dirA;
        impl_->pool->parallelFor(outerN, [&](int o0, int o1) {
            for (int o = o0; o < o1; ++o) {
                for (int in = 0; in < innerN; ++in) {
                    const int xb = bInner ? in : o, yc = bInner ? o : in;
                    const int c0 = std::clamp(yc + ic, 0, n[c] - 1), c1 = std::clamp(yc + ic + 1, 0, n[c] - 1);
                    const int b0 = std::clamp(xb + ib, 0, n[b] - 1), b1 = std::clamp(xb + ib + 1, 0, n[b] - 1);
                    const std::size_t p00 = at(prev, b0, c0), p10 = at(prev, b1, c0), p01 = at(prev, b0, c1),
                                      p11 = at(prev, b1, c1);
                    auto bilinear = [&](const float* f) {
                        return kernels::lerp(kernels::lerp(f[p00], f[p10], fb), kernels::lerp(f[p01], f[p11], fb), fc);
                    };
                    const std::size_t cell = at(sa, xb, yc);
                    tau[cell] = bilinear(tau.data()) + halfStep * (den[cell] + bilinear(den)) +
                                (built[cell] == kVoxelBuilt ? kOpaque : 0.f);
                }
            }
        });
    }
    transmittanceOf(*impl_->pool, tau, T);
}

namespace {

// The density a texture gets (see SmokeVolume::exportRG8), for every cell into `out`: a fluid
// cell's own; a built cell (wall, floor, ceiling, mesh) next to free space the smallest density
// among those free neighbours; a built cell one step further in the smallest among its
// neighbours of the layer before; six layers. A surface can lie anywhere in its first built cell,
// so a trilinear sample between the last fluid cell and the surface blends up to two built cells
// on each axis: six steps in a corner of three surfaces. Every other cell exports 0. The layers
// grow from a frontier list, so the cost is the wall skin's, not six sweeps of the grid.
// `source` (when not null) gets, for every cell, the free cell whose values it exports: itself
// for fluid cells, the neighbour whose density a wall cell took (followed back to free space) for
// the skin, and the cell itself elsewhere; so the lighting channels can follow the density.
void exportedDensity(const SmokeState& s, std::vector<float>& out, std::vector<std::size_t>* source = nullptr) {
    const GridInfo& g = s.grid;
    const std::size_t n = g.cells();
    out.assign(n, 0.f);
    if (source) {
        source->resize(n);
        for (std::size_t c = 0; c < n; ++c) (*source)[c] = c;
    }
    std::vector<std::uint8_t> layer(n, 0);  // l: the l-th layer of built cells
    const std::ptrdiff_t off[6] = {-1, 1, -s.dims.sy, s.dims.sy, -s.dims.sz, s.dims.sz};
    auto inside = [&](std::size_t c, int o) {  // the face neighbour o of c is in the grid
        const int i = static_cast<int>(c % static_cast<std::size_t>(g.nx));
        const int j = static_cast<int>((c / static_cast<std::size_t>(g.nx)) % static_cast<std::size_t>(g.ny));
        const int k = static_cast<int>(c / (static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.ny)));
        const int at[3] = {i, j, k}, size[3] = {g.nx, g.ny, g.nz};
        const int axis = o / 2, step = (o & 1) ? 1 : -1;
        return at[axis] + step >= 0 && at[axis] + step < size[axis];
    };
    // Layer l's value at built cell c: the least among neighbours that are free space (l = 1) or
    // of layer l - 1 (the first such neighbour on a tie); false if there are none.
    auto least = [&](std::size_t c, int l, float& value) {
        bool any = false;
        std::size_t from = c;
        for (int o = 0; o < 6; ++o) {
            if (!inside(c, o)) continue;
            const std::size_t m = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + off[o]);
            if (l == 1 ? s.voxelSolid[m] != 0 : layer[m] != l - 1) continue;
            const float v = l == 1 ? s.density[m] : out[m];
            if (!any || v < value) {
                value = v;
                from = m;
            }
            any = true;
        }
        if (any && source) (*source)[c] = (*source)[from];
        return any;
    };
    std::vector<std::size_t> frontier;
    for (std::size_t c = 0; c < n; ++c) {
        if (s.cellClass[c] == kFluid) out[c] = s.density[c];
        float v;
        if (s.voxelSolid[c] == kVoxelBuilt && least(c, 1, v)) {
            out[c] = v;
            layer[c] = 1;
            frontier.push_back(c);
        }
    }
    constexpr int kLayers = 6;
    std::vector<std::size_t> next;
    for (int l = 2; l <= kLayers && !frontier.empty(); ++l) {
        next.clear();
        for (std::size_t c : frontier)
            for (int o = 0; o < 6; ++o) {
                if (!inside(c, o)) continue;
                const std::size_t m = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + off[o]);
                if (s.voxelSolid[m] != kVoxelBuilt || layer[m] != 0) continue;
                float v = 0.f;
                least(m, l, v);  // true: c is one of its layer l - 1 neighbours
                out[m] = v;
                layer[m] = static_cast<std::uint8_t>(l);
                next.push_back(m);
            }
        frontier.swap(next);
    }
}

}  // namespace

void SmokeVolume::computeSkyVisibility() {
    const SmokeState& s = impl_->state;
    const GridInfo& g = s.grid;
    std::vector<float>& V = impl_->skyVisibility;
    std::vector<float>& tau = impl_->opticalDepth;
    tau.assign(g.cells(), 0.f);
    const float* den = s.density.data();
    const float halfStep = static_cast<float>(impl_->settings.shadowSigma * g.cellSize) * 0.5f;
    const std::ptrdiff_t sy = s.dims.sy, sz = s.dims.sz;
    // The top slice sees the sky through its own half cell.
    for (int k = 0; k < g.nz; ++k)
        for (int i = 0; i < g.nx; ++i) {
            const std::size_t c = g.index(i, g.ny - 1, k);
            tau[c] = halfStep * den[c];
        }
    // Each slice below: the slice above blurred by (1 2 1) x (1 2 1) / 16 (edges clamped), plus
    // half its own density and half the blurred density above.
    for (int j = g.ny - 2; j >= 0; --j) {
        impl_->pool->parallelFor(g.nz, [&](int k0, int k1) {
            for (int k = k0; k < k1; ++k) {
                const int ka = std::max(k - 1, 0), kb = std::min(k + 1, g.nz - 1);
                for (int i = 0; i < g.nx; ++i) {
                    const int ia = std::max(i - 1, 0), ib = std::min(i + 1, g.nx - 1);
                    const std::size_t up = static_cast<std::size_t>((j + 1) * sy);
                    auto blur = [&](const float* f) {
                        auto row = [&](int kk) {
                            const std::size_t r = up + static_cast<std::size_t>(kk * sz);
                            return f[r + static_cast<std::size_t>(ia)] + 2.f * f[r + static_cast<std::size_t>(i)] +
                                   f[r + static_cast<std::size_t>(ib)];
                        };
                        return (row(ka) + 2.f * row(k) + row(kb)) * 0.0625f;
                    };
                    const std::size_t c = g.index(i, j, k);
                    tau[c] = blur(tau.data()) + halfStep * (den[c] + blur(den));
                }
            }
        });
    }
    transmittanceOf(*impl_->pool, tau, V);
}

const std::vector<float>& SmokeVolume::skyVisibility() const { return impl_->skyVisibility; }

void SmokeVolume::computeLampTransmittance(const Vec3& lamp, std::vector<float>& out) const {
    const SmokeState& s = impl_->state;
    const GridInfo& g = s.grid;
    const Vec3 l = g.toCellCoords(lamp);
    if (!std::isfinite(l.x + l.y + l.z)) {
        out.assign(g.cells(), 1.f);
        return;
    }
    // The sweeps write each cell's optical depth into `out` (0, a transmittance of 1, where no
    // pyramid reaches: the lamp's own cell); one pass turns them into transmittances at the end.
    // expNeg outside the sweep: in it, its dependent chain of multiplies and adds was 40 % of the
    // sweep's samples (perf); a 2-lamp 64^3 upload took 10.5-13.9 ms, now 6.8-10.1 (alternating
    // runs of the two builds of a small driver, fastest of 10 each; the same bits: a hash of the
    // sun's and 4 lamps' maps unchanged).
    out.assign(g.cells(), 0.f);
    const double lc[3] = {l.x, l.y, l.z};
    const int n[3] = {g.nx, g.ny, g.nz};
    const std::size_t stride[3] = {1, static_cast<std::size_t>(g.nx), static_cast<std::size_t>(g.nx) * g.ny};
    const float* den = s.density.data();
    const std::uint8_t* built = s.voxelSolid.data();
    const float sigmaH = static_cast<float>(impl_->settings.shadowSigma * g.cellSize);  // optical depth a cell of density 1
    constexpr float kOpaque = 12.f;  // as computeTransmittance: a built cell passes e^-12
    const double clearance = kLampClearance / g.cellSize;  // cells
    // Pyramid p: the cells whose dominant offset from the lamp is along axis a = p / 2, on the
    // side sgn (the first axis wins a tie). Its planes are swept outwards, each over the pyramid's
    // square and a margin (a cell at the pyramid's edge reads the plane before up to a cell
    // outside it), and each writes only its own cells: every cell once, whatever the thread count.
    auto sweep = [&](int p) {
        const int a = p / 2, b = (a + 1) % 3, c = (a + 2) % 3, sgn = (p % 2) ? 1 : -1;
        const int nb = n[b], nc = n[c];
        std::vector<float> prev(static_cast<std::size_t>(nb) * nc, 0.f), cur(prev.size());
        int first = sgn > 0 ? std::max(0, static_cast<int>(std::floor(lc[a])) + 1)
                            : std::min(n[a] - 1, static_cast<int>(std::ceil(lc[a])) - 1);
        bool havePrev = false;  // prev holds the plane before, inside the grid
        for (int sa = first; sa >= 0 && sa < n[a]; sa += sgn) {
            const double D = std::fabs(sa - lc[a]);  // > 0: cells off the lamp along a
            const int pa = sa - sgn;                 // the plane before, towards the lamp
            const bool fromLamp = D <= 1.0;          // the plane before is at or past the lamp
            const double shrink = (D - 1.0) / D;     // where the ray to the lamp crosses plane pa
            // Only the pyramid's square on this plane, 2 cells wider: its cells read the plane
            // before within D - 1 + 1 of the lamp's axis (the bilinear's second texel), which that
            // plane's own square, D + 1 wide, holds.
            const auto span = [&](int axis, int count, int& lo, int& hi) {
                lo = std::max(0, static_cast<int>(std::floor(lc[axis] - D - 2)));
                hi = std::min(count - 1, static_cast<int>(std::ceil(lc[axis] + D + 2)));
            };
            int b0s, b1s, c0s, c1s;
            span(b, nb, b0s, b1s);
            span(c, nc, c0s, c1s);
            // The inner loop along the contiguous axis, as computeTransmittance's.
            const bool bInner = stride[b] < stride[c];
            const int o0 = bInner ? c0s : b0s, o1 = bInner ? c1s : b1s, i0 = bInner ? b0s : c0s, i1 = bInner ? b1s : c1s;
            for (int o = o0; o <= o1; ++o) {
                for (int in = i0; in <= i1; ++in) {
                    const int xb = bInner ? in : o, yc = bInner ? o : in;
                    const double db = xb - lc[b], dc = yc - lc[c];
                    const std::size_t cell = sa * stride[a] + xb * stride[b] + yc * stride[c];
                    const double dist = std::sqrt(D * D + db * db + dc * dc);  // cells to the lamp
                    const float rho = den[cell];
                    float tau;
                    if (fromLamp) {
                        tau = sigmaH * static_cast<float>(dist) * rho;  // the lamp's own neighbourhood
                    } else {
                        const float seg = sigmaH * static_cast<float>(dist / D);  // one plane's length of ray
                        float tauQ = 0.f, rhoQ = 0.f;                            // outside the grid: no smoke
                        const double ub = lc[b] + db * shrink, uc = lc[c] + dc * shrink;
                        // A crossing more than half a cell outside plane pa: the ray came in from
                        // outside the grid, where there is no smoke.
                        const bool inside = ub > -0.5 && ub < nb - 0.5 && uc > -0.5 && uc < nc - 0.5;
                        if (havePrev && inside) {
                            const double qb = std::clamp(ub, 0.0, nb - 1.0);
                            const double qc = std::clamp(uc, 0.0, nc - 1.0);
                            const int b0 = std::min(static_cast<int>(qb), nb - 2 < 0 ? 0 : nb - 2);
                            const int c0 = std::min(static_cast<int>(qc), nc - 2 < 0 ? 0 : nc - 2);
                            const int b1 = std::min(b0 + 1, nb - 1), c1 = std::min(c0 + 1, nc - 1);
                            const float fb = static_cast<float>(qb - b0), fc = static_cast<float>(qc - c0);
                            auto bilinear = [&](auto&& at) {
                                return kernels::lerp(kernels::lerp(at(b0, c0), at(b1, c0), fb),
                                                     kernels::lerp(at(b0, c1), at(b1, c1), fb), fc);
                            };
                            tauQ = bilinear([&](int x, int y) { return prev[static_cast<std::size_t>(y) * nb + x]; });
                            rhoQ = bilinear([&](int x, int y) { return den[pa * stride[a] + x * stride[b] + y * stride[c]]; });
                        }
                        tau = tauQ + seg * 0.5f * (rho + rhoQ);
                    }
                    const double chebyshev = std::max(D, std::max(std::fabs(db), std::fabs(dc)));
                    if (built[cell] == kVoxelBuilt && chebyshev > clearance) tau += kOpaque;
                    cur[static_cast<std::size_t>(yc) * nb + xb] = tau;
                    // This pyramid's cell: its offset along a is the largest (the lower axis on a tie).
                    const double off[3] = {a == 0 ? D : (b == 0 ? db : dc), a == 1 ? D : (b == 1 ? db : dc),
                                           a == 2 ? D : (b == 2 ? db : dc)};
                    bool mine = true;
                    for (int x = 0; x < 3 && mine; ++x)
                        if (x != a) mine = x < a ? std::fabs(off[x]) < D : std::fabs(off[x]) <= D;
                    if (mine) out[cell] = tau;
                }
            }
            prev.swap(cur);
            havePrev = true;
        }
    };
    impl_->pool->parallelFor(6, [&](int p0, int p1) {
        for (int p = p0; p < p1; ++p) sweep(p);
    });
    transmittanceOf(*impl_->pool, out, out);
}

void SmokeVolume::exportLampTransmittance(const std::vector<Vec3>& lamps, std::vector<float>& out) const {
    const std::size_t n = impl_->state.grid.cells();
    out.assign(4 * n, 1.f);
    if (lamps.empty()) return;
    std::vector<std::size_t>& source = impl_->exportSource;
    exportedDensity(impl_->state, impl_->exportScratch, &source);
    std::vector<float> T;
    for (std::size_t l = 0; l < lamps.size() && l < 4; ++l) {
        computeLampTransmittance(lamps[l], T);
        for (std::size_t c = 0; c < n; ++c) out[4 * c + l] = T[source[c]];
    }
}

void SmokeVolume::exportRG8(std::vector<std::uint8_t>& out) const {
    const SmokeState& s = impl_->state;
    const std::size_t n = s.grid.cells();
    std::vector<float>& density = impl_->exportScratch;
    exportedDensity(s, density);
    out.resize(2 * n);
    const float scale = 255.f / static_cast<float>(std::max(1e-6, impl_->settings.exportDensityScale));
    const float* T = impl_->transmittance.data();
    for (std::size_t c = 0; c < n; ++c) {
        out[2 * c] = static_cast<std::uint8_t>(kernels::clampf(density[c] * scale, 0.f, 255.f) + 0.5f);
        out[2 * c + 1] = static_cast<std::uint8_t>(kernels::clampf(T[c] * 255.f, 0.f, 255.f) + 0.5f);
    }
}

void SmokeVolume::exportRGFloat(std::vector<float>& out) const {
    const std::size_t n = impl_->state.grid.cells();
    std::vector<float>& density = impl_->exportScratch;
    exportedDensity(impl_->state, density);
    out.resize(2 * n);
    for (std::size_t c = 0; c < n; ++c) {
        out[2 * c] = density[c];
        out[2 * c + 1] = impl_->transmittance[c];
    }
}

void SmokeVolume::exportRGBFloat(std::vector<float>& out) const {
    const std::size_t n = impl_->state.grid.cells();
    std::vector<float>& density = impl_->exportScratch;
    std::vector<std::size_t>& source = impl_->exportSource;
    exportedDensity(impl_->state, density, &source);
    out.resize(3 * n);
    const float* T = impl_->transmittance.data();
    const float* V = impl_->skyVisibility.data();
    for (std::size_t c = 0; c < n; ++c) {
        out[3 * c] = density[c];
        out[3 * c + 1] = T[source[c]];
        out[3 * c + 2] = V[source[c]];
    }
}

void SmokeVolume::exportDensityFloat(std::vector<float>& out) const { exportedDensity(impl_->state, out); }

bool SmokeVolume::validate(std::string* problem) const {
    const SmokeState& s = impl_->state;
    const GridInfo& g = s.grid;
    auto fail = [&](const char* what, std::size_t c, float value) {
        if (problem) {
            std::ostringstream o;
            o << what << " at cell (" << c % g.nx << ", " << (c / g.nx) % g.ny << ", " << c / (static_cast<std::size_t>(g.nx) * g.ny)
              << "): " << value;
            *problem = o.str();
        }
        return false;
    };
    const std::vector<float>* fields[] = {&s.density, &s.temperature, &s.u, &s.v, &s.w, &s.pressure};
    const char* names[] = {"density", "temperature", "u", "v", "w", "pressure"};
    for (int f = 0; f < 6; ++f)
        for (std::size_t c = 0; c < fields[f]->size(); ++c)
            if (!std::isfinite((*fields[f])[c])) return fail(names[f], c, (*fields[f])[c]);
    for (std::size_t c = 0; c < s.density.size(); ++c) {
        if (s.density[c] < 0) return fail("negative density", c, s.density[c]);
        if (s.temperature[c] < 0) return fail("negative temperature", c, s.temperature[c]);
        if (s.cellClass[c] != kFluid && s.density[c] != 0) return fail("density in a non-fluid cell", c, s.density[c]);
    }
    for (float t : impl_->transmittance)
        if (!(t >= 0 && t <= 1)) return fail("transmittance out of [0, 1]", 0, t);
    return true;
}

}  // namespace obscura::smoke
