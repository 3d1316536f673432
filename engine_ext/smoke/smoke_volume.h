// SmokeVolume: one smoke grenade's cloud, simulated on its own grid (default 64^3 cells of 0.25 m,
// a 16 m box centred on the detonation point) against the level's brushes and meshes.
// Plain C++ (no OGRE): the renderer uploads exportRGBFloat() into a 3D texture and
// ray-marches it; the game steps it, feeds it moving obstacles and bullet rays (carve).
//
// Typical use:
//   auto vol = SmokeVolume::create(level, meshes, impactPoint);          // throws on bad input
//   each frame: vol.setMovingObstacles(players); vol.step(dt);
//               vol.computeTransmittance(towardSun); vol.computeSkyVisibility();
//               vol.exportRGBFloat(buffer);  // upload buffer
//   on a shot:  vol.carve(muzzle, direction, range, 0.3);
//   when vol.finished(): drop it (SmokeManager does this).
//
// Determinism: step() gives bitwise identical fields for any thread count (SmokeSettings::threads).
// Movable, not copyable; a moved-from volume may only be assigned to or destroyed.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/triangle_mesh.h"
#include "core/vec3.h"
#include "map/level.h"
#include "smoke/smoke_grid.h"
#include "smoke/smoke_settings.h"
#include "smoke/smoke_state.h"

namespace obscura::smoke {

class ThreadPool;

// Something that moves through the smoke and pushes it (players, grenades, props). Its cells are
// solid for one step and their faces move at `velocity` (free-slip against it).
struct MovingObstacle {
    enum class Shape { Sphere, Box };
    Shape shape = Shape::Sphere;
    Vec3 centre;
    double radius = 0.4;               // sphere, metres
    Vec3 halfExtents{0.3, 0.9, 0.3};   // box (axis-aligned), metres
    Vec3 velocity;                     // m/s
};

class SmokeVolume {
public:
    // Builds the grid around `centre` and voxelises the level's solid brushes and `meshes` into
    // it. Throws std::runtime_error with a readable message when the level has no brushes, the
    // centre is not finite, is outside the level's bounds or inside a solid brush, has no free cell
    // within two cells (meshes), or cellSize is not positive. A centre on a floor or against a wall
    // (its cell solid by conservative voxelisation) seeds from the nearest free cell. A resolution outside [16, 128] is clamped with a warning on stderr.
    // `pool`: share one thread pool between volumes (SmokeManager does); null = own pool of
    // settings.threads threads.
    static SmokeVolume create(const map::Level& level, const std::vector<TriangleMesh>& meshes, const Vec3& centre,
                              const SmokeSettings& settings = {}, std::shared_ptr<ThreadPool> pool = nullptr);

    SmokeVolume(SmokeVolume&&) noexcept;
    SmokeVolume& operator=(SmokeVolume&&) noexcept;
    ~SmokeVolume();

    // Advances by dt seconds (clamped to settings.maxStep; non-finite or <= 0 does nothing; split
    // into substeps when the flow is faster than maxCfl cells per step). Never throws.
    void step(double dt);
    // The same step through the scalar single-threaded reference solver (tests, benchmark).
    void stepReference(double dt);

    // Replaces the moving obstacles (takes effect from the next step). Smoke inside a newly
    // covered cell is pushed to its free neighbours.
    void setMovingObstacles(const std::vector<MovingObstacle>& obstacles);

    // A bullet: removes smoke within `radius` of the segment origin + t * direction, t in
    // [0, length] (all of it within radius / 2, a smoothstep edge out to the radius; each cell keeps
    // that profile's average over its volume, so the tunnel is round below the cell size) and gives
    // the air a wake along the ray (wakeSpeed m/s on the axis) so the tunnel closes by the flow.
    void carve(const Vec3& origin, const Vec3& direction, double length, double radius, double wakeSpeed = 3.0);

    double age() const;        // seconds simulated
    bool emitting() const;     // age < emitTime
    bool finished() const;     // age >= lifetime: drop it
    const GridInfo& grid() const;
    const SmokeSettings& settings() const;
    const SmokeStats& stats() const;  // of the last step
    Vec3 centre() const;
    int threads() const;

    // Density at a world point (trilinear; 0 outside the grid). For gameplay (line of sight, AI).
    double sampleDensity(const Vec3& world) const;
    // Optical depth of the smoke along a segment (sum of density x step), for line-of-sight tests.
    double opticalDepth(const Vec3& from, const Vec3& to) const;

    float densityAt(int i, int j, int k) const;
    bool solidAt(int i, int j, int k) const;       // the solver treats the cell as solid (any cause)
    bool voxelSolidAt(int i, int j, int k) const;  // the voxeliser marked it (brush / mesh / out of level)
    double totalDensity() const;   // sum of density x cell volume (m^3 density units), fixed order
    double maxDivergence() const;  // max |div u - source| over fluid cells now (1/s; the source of the last projection)

    // Transmittance toward a light: per cell exp(-shadowSigma * integral of density from the cell
    // toward the light), swept slice by slice along the light's dominant axis (bilinear in the
    // slice before). `towardLight` points from the smoke to the light.
    void computeTransmittance(const Vec3& towardLight);
    const std::vector<float>& transmittance() const;  // grid().cells() values, x fastest; 1 until computed
    // How open each cell is upwards through the smoke, for the renderer's ambient light (the smoke's
    // own occlusion: the level's, roofs and walls, is in the baked light, engine_ext/lightbake):
    // exp(-optical depth) swept down from the grid's top, each slice taking the slice above blurred
    // by a 3x3 binomial kernel (so it sees a widening cone, not one column), with the smoke at
    // shadowSigma. 1 with no smoke above, falling into a dense cloud.
    void computeSkyVisibility();
    const std::vector<float>& skyVisibility() const;  // grid().cells() values; 1 until computed
    // Transmittance towards a point light at `lamp` (world; inside the grid or not), for every
    // cell into `out` (grid().cells() values, x fastest): exp(-shadowSigma * the integral of
    // density along the segment from the cell's centre to the lamp, inside the grid), built cells
    // opaque as in computeTransmittance except within kLampClearance of the lamp (a lamp hangs on
    // its fixture). Swept outwards from the lamp in the six pyramids of its dominant axes, each
    // plane taking the plane before bilinearly where the ray to the lamp crosses it: one pass over
    // each pyramid, no ray marched per cell. For the renderer (the lamps and the signs' lamps
    // shadowed by the smoke they light); the solver's state is not touched.
    void computeLampTransmittance(const Vec3& lamp, std::vector<float>& out) const;
    static constexpr double kLampClearance = 0.5;  // metres: two cells, a fixture's size
    // Up to 4 lamps' transmittances packed as RGBA32F per cell (x fastest), channel c = lamps[c],
    // unused channels 1; a wall cell of the export's skin (exportRGBFloat) takes the value of the
    // free cell its density came from, so a trilinear sample at a wall is lit like the smoke
    // beside it. What the renderer uploads beside exportRGBFloat.
    void exportLampTransmittance(const std::vector<Vec3>& lamps, std::vector<float>& out) const;

    // Packed for a 3D texture of grid().nx x ny x nz (x fastest, then y, then z). The density
    // exported is the fluid cells' own; a built cell (wall, floor, ceiling, mesh) next to free
    // space gets the smallest density among those free neighbours, and a built cell behind that
    // one the smallest of its first-layer neighbours', so a trilinear sample between the last fluid
    // cell and a surface (wherever it lies in its cell) sees the smoke's density, not a fade to 0:
    // the smoke reaches the surface the renderer's depth test stops it at. (Smallest, so a
    // one-cell wall with smoke on one side only exports 0 and shows nothing on its clean side.)
    // Every other cell the smoke cannot enter exports 0.
    // The wall cells that get a density this way take the transmittance and sky visibility of the
    // same free neighbour (the one whose density they took), so a trilinear sample near a wall is
    // lit like the smoke beside it, not darkened by the wall's own (opaque) value.
    // RGB32F: (density, transmittance, sky visibility) per cell, unscaled (HDR: no clamp); what the
    // renderer uploads (PF_FLOAT32_RGB).
    void exportRGBFloat(std::vector<float>& out) const;
    // RG8: R = density / exportDensityScale (clamped to 1), G = transmittance, each 0..255.
    void exportRG8(std::vector<std::uint8_t>& out) const;
    // RG32F: (density, transmittance) pairs, unscaled.
    void exportRGFloat(std::vector<float>& out) const;
    // R32F: the density alone, unscaled (HDR: no clamp), one float per cell.
    void exportDensityFloat(std::vector<float>& out) const;

    // True when every field is finite, density and temperature are >= 0 and no non-fluid cell
    // holds density; otherwise false and `problem` says what and where.
    bool validate(std::string* problem = nullptr) const;

    // The raw state, for tests and the benchmark.
    const SmokeState& state() const;
    SmokeState& mutableState();

private:
    struct Impl;
    explicit SmokeVolume(std::unique_ptr<Impl> impl);
    void advance(double dt, bool reference);
    std::unique_ptr<Impl> impl_;
};

}  // namespace obscura::smoke
