// The truth key's tracer (plain C++ + Embree 3): the ray-traced AO of the current view
// (ssao/ao_reference.h), refined in passes on worker threads it owns, so the frame never waits.
//
// Each pass covers the whole image: the first finds every pixel's visible surface and shoots 8
// rays, each later one doubles the rays so far (8, 16, 32, ... up to `rays`). A pixel's rays come
// from its own generator (AoReference::pixelSeed), continued from pass to pass, so the finished
// image is bit for bit AoReference::render's at the same pose and ray count, for any number of
// threads. After each pass a snapshot (image, rays per pixel so far, done) is published; the render
// thread takes the latest with a pointer swap under a lock the workers hold for nothing longer.
// A request that differs from the one being traced (the camera moved beyond a few millimetres or
// a tenth of a degree, another size, radius or ray count) abandons it within a pixel and starts over.
#pragma once

#include "core/triangle_mesh.h"
#include "raytrace/camera_pose.h"
#include "ssao/ao_reference.h"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace obscura::ao_truth {

struct Request {
    CameraPose pose;
    int width = 0, height = 0;
    double radius = 0.6;
    int rays = 256;
    // Same view for the tracer: eye within kEyeEpsilon, angles within kAngleEpsilon, the rest equal.
    bool sameView(const Request& other) const;
};
// 5 mm and 0.1 degree: well under a pixel of the 320 x 180 reference at 90 degrees (0.28 degree a
// pixel), and more than the float jitter of an interpolated camera standing still.
constexpr double kEyeEpsilon = 0.005;
constexpr double kAngleEpsilon = 0.1 * 3.14159265358979323846 / 180.0;

struct Snapshot {
    Request request;
    ssao::AoImage image;   // 1 where no pass has reached yet (and for sky pixels)
    int rays = 0;          // per pixel so far (0: the first pass has not finished)
    bool done = false;     // rays == request.rays
    std::uint64_t serial = 0;  // grows with every snapshot published (a new one to upload)
    double seconds = 0;        // from the request to this snapshot (wall time; for the log, never a picture)
};

// 8, 16, 32, ... doubling up to `rays` (the last pass tops up to exactly `rays`).
std::vector<int> passRays(int rays);

class ProgressiveAo {
public:
    // The Embree scene is built on the first worker, not here: this returns at once.
    ProgressiveAo(std::vector<TriangleMesh> meshes, int threads);
    ~ProgressiveAo();  // stops the workers (each within a pixel) and joins them
    ProgressiveAo(const ProgressiveAo&) = delete;
    ProgressiveAo& operator=(const ProgressiveAo&) = delete;

    // Never waits for a pass: the same view (Request::sameView) keeps the work going, another
    // one abandons it and starts over.
    void request(const Request& request);
    // Stops tracing (nothing shown): the current request is dropped, its snapshot with it.
    void cancel();
    // The latest snapshot of the current request (null before its first pass finished).
    std::shared_ptr<const Snapshot> latest() const;
    // Blocks until the current request is finished or `timeout` passes; true when finished.
    // For tests and headless replay captures only, never inside the live game's frame.
    bool waitDone(std::chrono::milliseconds timeout) const;
    // Passes abandoned because the view changed (for tests and the README's figures).
    int restarts() const;

private:
    struct Job;
    void work();
    void tracePixel(Job& job, int pass, int x, int y);
    void publish(Job& job, int pass);

    std::vector<TriangleMesh> meshes_;
    std::unique_ptr<ssao::AoReference> reference_;
    std::once_flag built_;

    mutable std::mutex mutex_;  // guards everything below but the pixel data of a running pass
    mutable std::condition_variable changed_;
    bool stop_ = false;
    std::shared_ptr<Job> job_;
    std::uint64_t serial_ = 0;
    int restarts_ = 0;

    mutable std::mutex snapshotMutex_;  // held for a pointer swap only
    std::shared_ptr<const Snapshot> snapshot_;

    std::vector<std::thread> workers_;
};

}  // namespace obscura::ao_truth
