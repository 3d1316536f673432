// SmokePipeline: the smoke's CPU work (the solver's step, the transmittance towards the sun and the
// sky, the export the renderer uploads, the lamp choice and the lamp maps) on a worker thread,
// pipelined one step behind the simulation. Plain C++, no OGRE.
//
// The game thread queues what happened (spawn, carve) and, every solver step, step(): that waits
// for the step before (normally long done: it had a whole step's ticks of rendering to run beside),
// publishes its SmokeFrame and starts this one. So the frame the renderer draws at any tick is the
// one of the step issued at the step boundary before: one step (kSmokeStepSeconds) behind, whatever
// the thread timing. The worker runs the queued work in the order it was queued, which is the order
// the game thread saw it, so the volumes and everything exported from them are the same bits as a
// synchronous run's (smoke_pipeline_test.cpp), and a replay gives the same captures every run.
//
// Threads: the game thread calls everything here; the worker alone touches the manager between
// step() and the next wait (settled(), step(), the destructor).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "core/triangle_mesh.h"
#include "core/vec3.h"
#include "map/level.h"
#include "smoke/smoke_lamps.h"
#include "smoke/smoke_manager.h"

namespace obscura::smoke {

// One volume as the renderer uploads it after a step.
struct SmokeFrameVolume {
    int id = 0;
    GridInfo grid;
    std::vector<float> fields;  // exportRGBFloat: (density, transmittance to the sun, sky) a cell
    std::vector<float> lamps;   // exportLampTransmittance towards LampChoice::shadowed; empty if none
    std::vector<float> light;   // lampLight (smoke_lamp_light.h): the bound lamps' light, two RGBA a cell
    SmokeBox occupied;          // the cells holding visible smoke, one cell wider (trilinear reach)
};

// What the renderer draws: the volumes with visible smoke among the first SMOKE_MAX_VOLUMES (the
// march's samplers; the oldest are marched), the lamps that light them, and what it cost.
struct SmokeFrame {
    std::uint64_t version = 0;  // steps published so far; 0: nothing yet
    std::vector<SmokeFrameVolume> volumes;
    LampChoice lamps;
    // The worker's time for this step (ms): the releases (voxelising the level into a new grid)
    // and carves queued before it, the solver, the sun's and sky's sweeps, the export with the
    // occupied boxes, the lamp maps and the lamps' light on the grid.
    double commandMs = 0, stepMs = 0, lightMs = 0, exportMs = 0, lampMs = 0;
};

// The frame of `manager` as it is: the volumes' fields and occupied boxes, the lamp choice, the
// lamp maps, the lamps' light (out's buffers are reused). What the worker runs after each step.
void exportFrame(const SmokeManager& manager, const std::vector<SmokeLamp>& levelLamps,
                 const std::vector<SmokeLamp>& signLamps, SmokeFrame& out);

class SmokePipeline {
public:
    // `level` must outlive the pipeline (the worker voxelises against it).
    SmokePipeline(std::size_t maxVolumes, const SmokeSettings& settings, const map::Level& level,
                  std::vector<TriangleMesh> meshes);
    ~SmokePipeline();  // waits for the step in flight
    SmokePipeline(const SmokePipeline&) = delete;
    SmokePipeline& operator=(const SmokePipeline&) = delete;

    // The lamps that may light the smoke (the level's, the signs'); taken by the next step.
    void setLamps(std::vector<SmokeLamp> level, std::vector<SmokeLamp> signs);
    // Queued for the next step: a cloud released at `where` (a place where no grid fits is
    // reported on stderr by the worker, and nothing is released), a bullet's carve.
    void spawn(const Vec3& where);
    void carve(const Vec3& origin, const Vec3& direction, double length, double radius);
    // The step boundary: waits for the step in flight and publishes its frame, then starts the
    // queued work and a step of dt with these obstacles, lit from towardSun.
    void step(double dt, std::vector<MovingObstacle> obstacles, const Vec3& towardSun);

    const SmokeFrame& published() const { return front_; }
    // Whether the step in flight or the work queued may hold smoke: false once a step showed the
    // manager empty and nothing was spawned since (a spawn is only known to fail when it runs).
    bool mayHoldSmoke() const { return maybeLive_; }
    // Waits for the step in flight: the manager as it is after every step issued (but not the
    // work queued since). For tests and dumps; the frame never calls it.
    const SmokeManager& settled();

private:
    struct Command {
        enum class Kind { Spawn, Carve } kind;
        Vec3 a, b;  // spawn: where; carve: origin, direction
        double length = 0, radius = 0;
    };
    struct Job {
        std::vector<Command> commands;
        std::uint64_t version = 0;
        double dt = 0;
        std::vector<MovingObstacle> obstacles;
        Vec3 towardSun;
    };
    void workerLoop(std::size_t maxVolumes, const SmokeSettings& settings);
    void run(const Job& job);  // on the worker: into back_
    void wait();

    const map::Level& level_;
    std::vector<TriangleMesh> meshes_;
    std::unique_ptr<SmokeManager> manager_;  // made by the worker: the game thread never waits for the pool's threads to start
    std::vector<SmokeLamp> levelLamps_, signLamps_;
    std::vector<Command> pending_;  // queued since the last step()
    SmokeFrame front_, back_;
    bool maybeLive_ = false;  // the step in flight or the queued work may hold smoke
    std::uint64_t issued_ = 0;  // steps started

    std::mutex mutex_;
    std::condition_variable wake_, done_;
    Job job_;
    bool busy_ = true, stop_ = false;  // busy until the worker has made the manager
    std::thread worker_;  // last: started when everything above is ready
};

}  // namespace obscura::smoke
