// See ao_reference.h.
#include "ssao/ao_reference.h"

#include "core/rng.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

namespace obscura::ssao {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Rays start this far off the surface so they do not hit the triangle they leave (metres).
constexpr float kRayOffset = 1e-3f;
}  // namespace

struct AoReference::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;

    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }

    bool occluded(const Vec3& o, const Vec3& d, float tfar) const {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRay ray{};
        ray.org_x = static_cast<float>(o.x);
        ray.org_y = static_cast<float>(o.y);
        ray.org_z = static_cast<float>(o.z);
        ray.dir_x = static_cast<float>(d.x);
        ray.dir_y = static_cast<float>(d.y);
        ray.dir_z = static_cast<float>(d.z);
        ray.tnear = kRayOffset;
        ray.tfar = tfar;
        ray.mask = 0xffffffffu;
        rtcOccluded1(scene, &ctx, &ray);
        return ray.tfar < 0;  // Embree sets tfar to -inf on a hit
    }
};

AoReference::AoReference(const std::vector<TriangleMesh>& meshes) : impl_(std::make_unique<Impl>()) {
    impl_->device = rtcNewDevice("threads=1");  // we parallelise over pixels ourselves
    if (!impl_->device) throw std::runtime_error("Embree: cannot create a device");
    impl_->scene = rtcNewScene(impl_->device);
    for (const auto& m : meshes) {
        if (m.indices.size() < 3) continue;
        RTCGeometry g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), m.vertices.size()));
        for (std::size_t i = 0; i < m.vertices.size(); ++i) {
            v[3 * i] = static_cast<float>(m.vertices[i].x);
            v[3 * i + 1] = static_cast<float>(m.vertices[i].y);
            v[3 * i + 2] = static_cast<float>(m.vertices[i].z);
        }
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), m.indices.size() / 3));
        for (std::size_t i = 0; i < m.indices.size() / 3 * 3; ++i) idx[i] = m.indices[i];
        rtcCommitGeometry(g);
        rtcAttachGeometry(impl_->scene, g);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(impl_->scene);
}

AoReference::~AoReference() = default;

double AoReference::aoAt(const Vec3& p, const Vec3& n, double radius, int rays, std::uint64_t seed) const {
    // An orthonormal frame around the normal, then cosine-weighted directions (Malley's method).
    const Vec3 a = std::fabs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 t = normalize(cross(a, n)), b = cross(n, t);
    Rng rng(seed);
    int open = 0;
    for (int i = 0; i < rays; ++i) {
        const double u1 = rng.uniform01d(), u2 = rng.uniform01d();
        const double r = std::sqrt(u1), phi = 2 * kPi * u2;
        const Vec3 d = t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * std::sqrt(std::max(0.0, 1 - u1));
        open += !impl_->occluded(p + n * kRayOffset, d, static_cast<float>(radius));
    }
    return rays > 0 ? static_cast<double>(open) / rays : 1.0;
}

AoImage AoReference::render(const CameraPose& pose, int width, int height, double radius, int rays, int threads) const {
    AoImage img;
    img.width = width;
    img.height = height;
    img.ao.assign(static_cast<std::size_t>(width) * height, 1.0f);
    img.hit.assign(img.ao.size(), 0);
    const double tanX = std::tan(pose.fovX * kPi / 360.0), tanY = tanX * height / width;
    const double cy = std::cos(pose.yaw), sy = std::sin(pose.yaw), cp = std::cos(pose.pitch), sp = std::sin(pose.pitch);
    auto toWorld = [&](const Vec3& c) {  // camera -> world: pitch about X, then yaw about Y
        const Vec3 q{c.x, c.y * cp - c.z * sp, c.y * sp + c.z * cp};
        return Vec3{q.x * cy + q.z * sy, q.y, -q.x * sy + q.z * cy};
    };
    auto rowJob = [&](int y0) {
        for (int y = y0; y < height; y += threads)
            for (int x = 0; x < width; ++x) {
                const Vec3 dir = normalize(toWorld({(2.0 * (x + 0.5) / width - 1.0) * tanX,
                                                    (1.0 - 2.0 * (y + 0.5) / height) * tanY, -1.0}));
                RTCIntersectContext ctx;
                rtcInitIntersectContext(&ctx);
                RTCRayHit rh{};
                rh.ray.org_x = static_cast<float>(pose.eye.x);
                rh.ray.org_y = static_cast<float>(pose.eye.y);
                rh.ray.org_z = static_cast<float>(pose.eye.z);
                rh.ray.dir_x = static_cast<float>(dir.x);
                rh.ray.dir_y = static_cast<float>(dir.y);
                rh.ray.dir_z = static_cast<float>(dir.z);
                rh.ray.tnear = 0;
                rh.ray.tfar = std::numeric_limits<float>::infinity();
                rh.ray.mask = 0xffffffffu;
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(impl_->scene, &ctx, &rh);
                if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
                Vec3 n = normalize(Vec3{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z});
                if (dot(n, dir) > 0) n = -n;  // the side facing the camera
                const Vec3 p = pose.eye + dir * static_cast<double>(rh.ray.tfar);
                const auto i = static_cast<std::size_t>(y) * width + x;
                img.hit[i] = 1;
                img.ao[i] = static_cast<float>(aoAt(p, n, radius, rays, 0x9e3779b97f4a7c15ULL ^ i));
            }
    };
    threads = std::max(1, threads);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(rowJob, t);
    for (auto& th : pool) th.join();
    return img;
}

}  // namespace obscura::ssao
