// See level_chunks.h.
#include "render/level_chunks.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace obscura::render {

namespace {
struct ChunkKey {
    long x, y, z;
    bool sky;
    bool operator<(const ChunkKey& o) const { return std::tie(x, y, z, sky) < std::tie(o.x, o.y, o.z, o.sky); }
};

double axis(const Vec3& v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }

map::LevelVertex lerp(const map::LevelVertex& a, const map::LevelVertex& b, double t) {
    map::LevelVertex v;
    v.position = a.position + (b.position - a.position) * t;
    v.normal = a.normal;
    v.u = a.u + (b.u - a.u) * t;
    v.v = a.v + (b.v - a.v) * t;
    return v;
}

// The part of a convex polygon on one side of the plane `axis a = at` (below: <=, else >=).
std::vector<map::LevelVertex> clip(const std::vector<map::LevelVertex>& in, int a, double at, bool below) {
    std::vector<map::LevelVertex> out;
    const auto side = [&](const map::LevelVertex& v) { return below ? at - axis(v.position, a) : axis(v.position, a) - at; };
    for (std::size_t i = 0; i < in.size(); ++i) {
        const map::LevelVertex& p = in[i];
        const map::LevelVertex& q = in[(i + 1) % in.size()];
        const double sp = side(p), sq = side(q);
        if (sp >= 0) out.push_back(p);
        if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) out.push_back(lerp(p, q, sp / (sp - sq)));
    }
    return out.size() >= 3 ? out : std::vector<map::LevelVertex>{};
}

void bound(LevelChunk& c) {
    map::Aabb box;
    for (const auto& p : c.polygons)
        for (const auto& v : p.vertices) box.extend(v.position);
    c.centre = (box.min + box.max) * 0.5;
    c.radius = 0;
    for (const auto& p : c.polygons)
        for (const auto& v : p.vertices) c.radius = std::max(c.radius, length(v.position - c.centre));
}

map::Aabb boxOf(const LevelChunk& c) {
    map::Aabb box;
    for (const auto& p : c.polygons)
        for (const auto& v : p.vertices) box.extend(v.position);
    return box;
}

void splitInto(LevelChunk chunk, const std::vector<LightSphere>& lights, std::size_t maxLights, std::vector<LevelChunk>& out,
               ChunkStats& stats) {
    bound(chunk);
    chunk.lightsReaching = chunk.sky ? 0 : lightsReaching(chunk.centre, chunk.radius, lights);
    const map::Aabb box = boxOf(chunk);
    const Vec3 size = box.max - box.min;
    const int a = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    if (chunk.sky || chunk.lightsReaching <= maxLights || axis(size, a) < kMinChunkEdge) {
        if (chunk.lightsReaching > maxLights) ++stats.overfull;
        stats.mostLights = std::max(stats.mostLights, chunk.lightsReaching);
        out.push_back(std::move(chunk));
        return;
    }
    ++stats.split;
    const double at = axis(box.min + box.max, a) * 0.5;
    LevelChunk halves[2];
    for (auto& h : halves) h.sky = chunk.sky;
    for (const ChunkPolygon& p : chunk.polygons)
        for (int side = 0; side < 2; ++side) {
            std::vector<map::LevelVertex> part = clip(p.vertices, a, at, side == 0);
            if (!part.empty()) halves[side].polygons.push_back({p.texture, std::move(part)});
        }
    for (auto& h : halves)
        if (!h.polygons.empty()) splitInto(std::move(h), lights, maxLights, out, stats);
}
}  // namespace

std::size_t lightsReaching(const Vec3& centre, double radius, const std::vector<LightSphere>& lights) {
    std::size_t n = 0;
    for (const auto& l : lights) n += length(l.position - centre) <= l.reach + radius + 1e-3;
    return n;
}

std::vector<LevelChunk> buildChunks(const map::Level& level, double chunkSize, const std::vector<LightSphere>& lights,
                                    std::size_t maxLights, const std::function<bool(const std::string&)>& isSky,
                                    ChunkStats* stats) {
    std::map<ChunkKey, LevelChunk> cells;
    for (const auto& brush : level.brushes) {
        if (!brush.visible) continue;
        for (const auto& poly : brush.faces) {
            if (!poly.visible || poly.vertices.size() < 3) continue;
            Vec3 c;
            for (const auto& v : poly.vertices) c += v.position;
            c = c / static_cast<double>(poly.vertices.size());
            const bool sky = isSky(poly.texture);
            const ChunkKey key{static_cast<long>(std::floor(c.x / chunkSize)), static_cast<long>(std::floor(c.y / chunkSize)),
                               static_cast<long>(std::floor(c.z / chunkSize)), sky};
            LevelChunk& chunk = cells[key];
            chunk.sky = sky;
            chunk.polygons.push_back({poly.texture, poly.vertices});
        }
    }
    ChunkStats local;
    std::vector<LevelChunk> out;
    for (auto& [key, chunk] : cells) splitInto(std::move(chunk), lights, maxLights, out, local);
    if (stats) *stats = local;
    return out;
}

}  // namespace obscura::render
