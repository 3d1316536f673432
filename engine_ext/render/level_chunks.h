// The level's visible faces grouped into chunks for drawing (plain C++, no OGRE; LevelGeometry
// makes one ManualObject per chunk, on a scene node at the chunk's centre so OGRE's bounding sphere
// is the chunk's own). buildChunks can also cut a chunk reached by more than a number of lights in
// two along its longest axis (faces across the cut clipped) until none is: the way to keep OGRE's
// per-pass light list (8 lights in Debian's OGRE) complete. The game no longer needs it (level.frag
// reads every light from the light grid, light_grid.h) and passes no limit; e3m4 cut to 7 lights a
// chunk made 18,519 chunks of its 258.
#pragma once

#include "map/level.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace obscura::render {

struct ChunkPolygon {
    std::string texture;
    std::vector<map::LevelVertex> vertices;  // convex, world space (clipped from the level's face)
};

struct LevelChunk {
    bool sky = false;  // sky faces: drawn apart, lit by nothing, never split
    std::vector<ChunkPolygon> polygons;
    Vec3 centre;         // the middle of the chunk's box: its scene node's position
    double radius = 0;   // the farthest vertex from the centre (OGRE's bounding radius)
    std::size_t lightsReaching = 0;
};

struct LightSphere {
    Vec3 position;
    double reach = 0;  // metres
};

struct ChunkStats {
    std::size_t split = 0;     // cuts made to bring chunks under the light limit
    std::size_t overfull = 0;  // chunks still reached by more than the limit (smaller than kMinChunkEdge)
    std::size_t mostLights = 0;  // the most lights reaching one (non-sky) chunk
};

// A chunk is not cut below this edge, metres: more lights than the limit overlapping within half a
// metre is a map to fix, not a case to split for (the overfull count reports it).
constexpr double kMinChunkEdge = 0.5;

// Groups visible faces by `chunkSize` cells (of their centroid, sky apart), then cuts any non-sky
// chunk reached by more than `maxLights` of `lights`.
std::vector<LevelChunk> buildChunks(const map::Level& level, double chunkSize, const std::vector<LightSphere>& lights,
                                    std::size_t maxLights, const std::function<bool(const std::string&)>& isSky,
                                    ChunkStats* stats = nullptr);

// How many of `lights` reach a sphere (centre, radius), as OGRE counts point lights (plus a
// millimetre for its float arithmetic: never fewer than OGRE).
std::size_t lightsReaching(const Vec3& centre, double radius, const std::vector<LightSphere>& lights);

}  // namespace obscura::render
