// SmokeVolume's read side: accessors, sampling, transmittance, texture export, validation.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "smoke/smoke_volume.h"
#include "smoke/smoke_volume_impl.h"
#include "smoke/thread_pool.h"

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
    const float emit = s.age < impl_->settings.emitTime ? 1.f : 0.f;
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

void SmokeVolume::computeTransmittance(const Vec3& towardLight) {
    const SmokeState& s = impl_->state;
    std::vector<float>& T = impl_->transmittance;
    const Vec3 L = normalize(towardLight);
    if (dot(L, L) == 0 || !std::isfinite(L.x + L.y + L.z)) {
        std::fill(T.begin(), T.end(), 1.f);
        return;
    }
    // Sweep along the dominant axis a, starting at the light's side.
    const double comp[3] = {L.x, L.y, L.z};
    int a = 0;
    for (int x = 1; x < 3; ++x)
        if (std::fabs(comp[x]) > std::fabs(comp[a])) a = x;
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const int n[3] = {s.grid.nx, s.grid.ny, s.grid.nz};
    const std::ptrdiff_t stride[3] = {1, s.dims.sy, s.dims.sz};
    const int dirA = comp[a] > 0 ? 1 : -1;  // the previous slice (toward the light) is at +dirA
    const float ob = static_cast<float>(comp[b] / std::fabs(comp[a])), oc = static_cast<float>(comp[c] / std::fabs(comp[a]));
    const float stepLen = static_cast<float>(s.grid.cellSize / std::fabs(comp[a]));  // metres per slice
    const float sigma = static_cast<float>(impl_->settings.shadowSigma);
    std::vector<float> tau(static_cast<std::size_t>(n[b]) * n[c], 0.f), prevTau(tau.size(), 0.f),
        prevDen(tau.size(), 0.f);
    auto bilinear = [&](const std::vector<float>& f, float x, float y) {
        x = kernels::clampf(x, 0.f, static_cast<float>(n[b] - 1));
        y = kernels::clampf(y, 0.f, static_cast<float>(n[c] - 1));
        const int x0 = std::min(static_cast<int>(x), n[b] - 2), y0 = std::min(static_cast<int>(y), n[c] - 2);
        const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
        const std::size_t r0 = static_cast<std::size_t>(y0) * n[b] + x0, r1 = r0 + static_cast<std::size_t>(n[b]);
        return kernels::lerp(kernels::lerp(f[r0], f[r0 + 1], fx), kernels::lerp(f[r1], f[r1 + 1], fx), fy);
    };
    const int first = dirA > 0 ? n[a] - 1 : 0;
    for (int step = 0; step < n[a]; ++step) {
        const int sa = first - dirA * step;
        for (int yc = 0; yc < n[c]; ++yc)
            for (int xb = 0; xb < n[b]; ++xb) {
                const std::size_t cell = static_cast<std::size_t>(sa * stride[a] + xb * stride[b] + yc * stride[c]);
                const std::size_t slot = static_cast<std::size_t>(yc) * n[b] + xb;
                const float den = s.density[cell];
                float t = 0.f;
                if (step > 0) {  // half of this cell's density and half of the sample toward the light
                    const float px = static_cast<float>(xb) + ob, py = static_cast<float>(yc) + oc;
                    t = bilinear(prevTau, px, py) + sigma * stepLen * 0.5f * (den + bilinear(prevDen, px, py));
                }
                tau[slot] = t;
                T[cell] = std::exp(-t);
            }
        // This slice becomes the previous one.
        std::swap(prevTau, tau);
        for (int yc = 0; yc < n[c]; ++yc)
            for (int xb = 0; xb < n[b]; ++xb)
                prevDen[static_cast<std::size_t>(yc) * n[b] + xb] =
                    s.density[static_cast<std::size_t>(sa * stride[a] + xb * stride[b] + yc * stride[c])];
    }
}

void SmokeVolume::exportRG8(std::vector<std::uint8_t>& out) const {
    const SmokeState& s = impl_->state;
    const std::size_t n = s.grid.cells();
    out.resize(2 * n);
    const float scale = 255.f / static_cast<float>(std::max(1e-6, impl_->settings.exportDensityScale));
    const float* T = impl_->transmittance.data();
    for (std::size_t c = 0; c < n; ++c) {
        out[2 * c] = static_cast<std::uint8_t>(kernels::clampf(s.density[c] * scale, 0.f, 255.f) + 0.5f);
        out[2 * c + 1] = static_cast<std::uint8_t>(kernels::clampf(T[c] * 255.f, 0.f, 255.f) + 0.5f);
    }
}

void SmokeVolume::exportRGFloat(std::vector<float>& out) const {
    const SmokeState& s = impl_->state;
    const std::size_t n = s.grid.cells();
    out.resize(2 * n);
    for (std::size_t c = 0; c < n; ++c) {
        out[2 * c] = s.density[c];
        out[2 * c + 1] = impl_->transmittance[c];
    }
}

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
