// See ray_scene.h.
#include "raytrace/ray_scene.h"

#include <embree3/rtcore.h>

#include <stdexcept>

namespace obscura {

struct RayScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

namespace {
RTCRay makeRay(const Vec3& o, const Vec3& d, double tnear, double tfar) {
    RTCRay ray{};
    ray.org_x = static_cast<float>(o.x);
    ray.org_y = static_cast<float>(o.y);
    ray.org_z = static_cast<float>(o.z);
    ray.dir_x = static_cast<float>(d.x);
    ray.dir_y = static_cast<float>(d.y);
    ray.dir_z = static_cast<float>(d.z);
    ray.tnear = static_cast<float>(tnear);
    ray.tfar = static_cast<float>(tfar);
    ray.mask = 0xffffffffu;
    return ray;
}
}  // namespace

RayScene::RayScene(const std::vector<TriangleMesh>& meshes) : impl_(std::make_unique<Impl>()) {
    impl_->device = rtcNewDevice("threads=1");  // the callers parallelise over pixels themselves
    if (!impl_->device) throw std::runtime_error("Embree: cannot create a device");
    impl_->scene = rtcNewScene(impl_->device);
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        const TriangleMesh& m = meshes[k];
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
        rtcAttachGeometryByID(impl_->scene, g, static_cast<unsigned>(k));  // geomID = the mesh's index
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(impl_->scene);
}

RayScene::~RayScene() = default;

bool RayScene::occluded(const Vec3& o, const Vec3& d, double tnear, double tfar) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRay ray = makeRay(o, d, tnear, tfar);
    rtcOccluded1(impl_->scene, &ctx, &ray);
    return ray.tfar < 0;  // Embree sets tfar to -inf on a hit
}

bool RayScene::intersect(const Vec3& o, const Vec3& d, double tnear, double tfar, double& t, Vec3& normal) const {
    Hit hit;
    if (!intersect(o, d, tnear, tfar, hit)) return false;
    t = hit.t;
    normal = hit.normal;
    return true;
}

bool RayScene::intersect(const Vec3& o, const Vec3& d, double tnear, double tfar, Hit& hit) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh{};
    rh.ray = makeRay(o, d, tnear, tfar);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->scene, &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hit.t = rh.ray.tfar;
    hit.normal = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
    hit.mesh = rh.hit.geomID;
    hit.triangle = rh.hit.primID;
    return true;
}

}  // namespace obscura
