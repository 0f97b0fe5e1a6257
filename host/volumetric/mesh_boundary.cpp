#include "volumetric/mesh_boundary.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "util/error.h"

namespace tsis {

struct MeshBoundary::Scene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    ~Scene() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

MeshBoundary::MeshBoundary(const Mesh& mesh) : scene_(std::make_unique<Scene>()), mesh_(mesh) {
    scene_->device = rtcNewDevice("threads=1");
    if (!scene_->device)
        fail("Embree: cannot create a device (error ", rtcGetDeviceError(nullptr), ")");
    scene_->scene = rtcNewScene(scene_->device);
    rtcSetSceneBuildQuality(scene_->scene, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geom = rtcNewGeometry(scene_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                          mesh.positions.size()));
    auto* idx = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), mesh.triangles.size()));
    double extent = 0;
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            v[3 * i + static_cast<size_t>(c)] = mesh.positions[i][c];
            extent = std::max(extent, static_cast<double>(std::abs(mesh.positions[i][c])));
        }
    }
    facetNormals_.resize(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        for (int c = 0; c < 3; ++c) idx[3 * t + static_cast<size_t>(c)] = tri[c];
        const glm::dvec3 a(mesh.positions[tri.x]), b(mesh.positions[tri.y]),
            c(mesh.positions[tri.z]);
        glm::dvec3 n = glm::cross(b - a, c - a);
        const double len = glm::length(n);
        n = len > 0 ? n / len : glm::dvec3(0.0);
        // Outward by the winding; vertex normals settle a mesh wound inside out.
        if (mesh.hasNormals()) {
            const glm::dvec3 s(mesh.normals[tri.x] + mesh.normals[tri.y] + mesh.normals[tri.z]);
            if (glm::dot(s, n) < 0) n = -n;
        }
        facetNormals_[t] = n;
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_->scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene_->scene);
    // Embree intersects in float: offsets well above its rounding at this size.
    epsilon_ = 2e-6 * std::max(1.0, extent);
}

MeshBoundary::~MeshBoundary() = default;

bool MeshBoundary::intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tMax,
                             SurfaceHit& hit) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = static_cast<float>(origin.x);
    rh.ray.org_y = static_cast<float>(origin.y);
    rh.ray.org_z = static_cast<float>(origin.z);
    rh.ray.dir_x = static_cast<float>(dir.x);
    rh.ray.dir_y = static_cast<float>(dir.y);
    rh.ray.dir_z = static_cast<float>(dir.z);
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = std::isinf(tMax) ? INFINITY : static_cast<float>(tMax);
    rh.ray.mask = 0xffffffffu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_->scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    const glm::uvec3 tri = mesh_.triangles[rh.hit.primID];
    hit.facet = static_cast<int>(rh.hit.primID);
    hit.u = rh.hit.u;
    hit.v = rh.hit.v;
    hit.position = (1.0 - hit.u - hit.v) * glm::dvec3(mesh_.positions[tri.x]) +
                   hit.u * glm::dvec3(mesh_.positions[tri.y]) +
                   hit.v * glm::dvec3(mesh_.positions[tri.z]);
    hit.t = glm::dot(hit.position - origin, dir);
    hit.normal = facetNormals_[rh.hit.primID];
    return true;
}

glm::dvec3 MeshBoundary::shadingNormal(const SurfaceHit& hit) const {
    if (!mesh_.hasNormals()) return hit.normal;
    const glm::uvec3 tri = mesh_.triangles[static_cast<size_t>(hit.facet)];
    const glm::dvec3 n = (1.0 - hit.u - hit.v) * glm::dvec3(mesh_.normals[tri.x]) +
                         hit.u * glm::dvec3(mesh_.normals[tri.y]) +
                         hit.v * glm::dvec3(mesh_.normals[tri.z]);
    const double len = glm::length(n);
    return len > 0 ? n / len : hit.normal;
}

}  // namespace tsis
