// See progressive_ao.h.
#include "ao_truth/progressive_ao.h"

#include "core/rng.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace obscura::ao_truth {

bool Request::sameView(const Request& o) const {
    const Vec3 d = pose.eye - o.pose.eye;
    return width == o.width && height == o.height && radius == o.radius && rays == o.rays && pose.fovX == o.pose.fovX &&
           std::sqrt(dot(d, d)) <= kEyeEpsilon && std::fabs(std::remainder(pose.yaw - o.pose.yaw, 2 * 3.14159265358979323846)) <= kAngleEpsilon &&
           std::fabs(pose.pitch - o.pose.pitch) <= kAngleEpsilon;
}

std::vector<int> passRays(int rays) {
    // 8 rays first: every pixel's coarse AO in a thirty-second of the finished trace's time.
    std::vector<int> p;
    for (int r = 8; r < rays; r *= 2) p.push_back(r);
    p.push_back(std::max(1, rays));
    return p;
}

// One row's per-pixel state, made by the worker that traces the row's first pass.
struct Row {
    std::vector<Vec3> point, normal;
    std::vector<Rng> rng;
    std::vector<int> open;
    std::vector<std::uint8_t> hit;
};

struct ProgressiveAo::Job {
    explicit Job(const Request& r) : request(r), passes(passRays(r.rays)), rows(static_cast<std::size_t>(r.height)) {}
    const Request request;
    const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    const std::vector<int> passes;  // rays per pixel once each pass is done
    std::vector<Row> rows;          // a running pass's rows are each touched by one worker only
    // Guarded by ProgressiveAo::mutex_:
    int pass = 0, nextRow = 0, rowsDone = 0;
    bool done = false;
    std::atomic<bool> abandoned{false};  // read by the workers between pixels
};

ProgressiveAo::ProgressiveAo(std::vector<TriangleMesh> meshes, int threads) : meshes_(std::move(meshes)) {
    for (int t = 0; t < std::max(1, threads); ++t) workers_.emplace_back([this] { work(); });
}

ProgressiveAo::~ProgressiveAo() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
        if (job_) job_->abandoned = true;
    }
    changed_.notify_all();
    for (auto& w : workers_) w.join();
}

void ProgressiveAo::request(const Request& r) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (job_ && job_->request.sameView(r)) return;
        if (job_) {
            restarts_ += job_->done ? 0 : 1;
            job_->abandoned = true;
        }
        job_ = std::make_shared<Job>(r);  // small: the rows' state is made by the workers
        // The old view's picture is not this one's. Under mutex_ (then snapshotMutex_, as publish
        // takes them), so a first pass published meanwhile is never dropped after it.
        std::lock_guard<std::mutex> swap(snapshotMutex_);
        snapshot_.reset();
    }
    changed_.notify_all();
}

void ProgressiveAo::cancel() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!job_) return;
        restarts_ += job_->done ? 0 : 1;
        job_->abandoned = true;
        job_.reset();
        std::lock_guard<std::mutex> swap(snapshotMutex_);
        snapshot_.reset();
    }
}

std::shared_ptr<const Snapshot> ProgressiveAo::latest() const {
    std::lock_guard<std::mutex> lock(snapshotMutex_);
    return snapshot_;
}

bool ProgressiveAo::waitDone(std::chrono::milliseconds timeout) const {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, timeout, [this] { return job_ && job_->done; });
}

int ProgressiveAo::restarts() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return restarts_;
}

void ProgressiveAo::work() {
    std::call_once(built_, [this] { reference_ = std::make_unique<ssao::AoReference>(meshes_); });
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        changed_.wait(lock, [this] { return stop_ || (job_ && !job_->done && job_->nextRow < job_->request.height); });
        if (stop_) return;
        const std::shared_ptr<Job> job = job_;
        const int pass = job->pass, y = job->nextRow++;
        lock.unlock();
        bool complete = true;
        for (int x = 0; x < job->request.width && complete; ++x) {
            complete = !job->abandoned;
            if (complete) tracePixel(*job, pass, x, y);
        }
        lock.lock();
        if (!complete || job != job_ || ++job->rowsDone < job->request.height) continue;
        // The pass is complete and no worker touches its rows until the next one starts.
        lock.unlock();
        publish(*job, pass);
        lock.lock();
        if (job != job_) continue;
        if (pass + 1 == static_cast<int>(job->passes.size())) {
            job->done = true;
        } else {
            ++job->pass;
            job->nextRow = job->rowsDone = 0;
        }
        changed_.notify_all();
    }
}

void ProgressiveAo::tracePixel(Job& job, int pass, int x, int y) {
    const Request& r = job.request;
    Row& row = job.rows[static_cast<std::size_t>(y)];
    if (pass == 0) {
        if (x == 0) {
            row.point.resize(static_cast<std::size_t>(r.width));
            row.normal.resize(row.point.size());
            row.rng.resize(row.point.size());
            row.open.assign(row.point.size(), 0);
            row.hit.assign(row.point.size(), 0);
        }
        row.hit[x] = reference_->visibleSurface(r.pose, r.width, r.height, x, y, row.point[x], row.normal[x]);
        row.rng[x].reseed(ssao::AoReference::pixelSeed(static_cast<std::size_t>(y) * r.width + x));
    }
    if (!row.hit[x]) return;
    const int rays = job.passes[pass] - (pass > 0 ? job.passes[pass - 1] : 0);
    row.open[x] += reference_->openRays(row.point[x], row.normal[x], r.radius, rays, row.rng[x]);
}

void ProgressiveAo::publish(Job& job, int pass) {
    auto s = std::make_shared<Snapshot>();
    s->request = job.request;
    s->rays = job.passes[pass];
    s->done = pass + 1 == static_cast<int>(job.passes.size());
    s->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - job.start).count();
    ssao::AoImage& img = s->image;
    img.width = job.request.width;
    img.height = job.request.height;
    img.ao.assign(static_cast<std::size_t>(img.width) * img.height, 1.0f);
    img.hit.assign(img.ao.size(), 0);
    for (int y = 0; y < img.height; ++y) {
        const Row& row = job.rows[static_cast<std::size_t>(y)];
        for (int x = 0; x < img.width; ++x) {
            if (!row.hit[x]) continue;
            const auto i = static_cast<std::size_t>(y) * img.width + x;
            img.hit[i] = 1;
            // As AoReference::aoAt divides: the finished image is render()'s to the bit.
            img.ao[i] = static_cast<float>(static_cast<double>(row.open[x]) / s->rays);
        }
    }
    std::lock_guard<std::mutex> lock(mutex_);  // a newer request may have replaced this one
    if (job_.get() != &job) return;
    s->serial = ++serial_;
    std::lock_guard<std::mutex> swap(snapshotMutex_);
    snapshot_ = std::move(s);
}

}  // namespace obscura::ao_truth
