#include "volumetric/mesh_boundary.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/ext/vector_int3_sized.hpp>
#include <glm/geometric.hpp>

#include "mesh/weld.h"
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
    buildNeighbours();
}

MeshBoundary::~MeshBoundary() = default;

void MeshBoundary::buildNeighbours() {
    const std::vector<uint32_t> welded = weldPositions(mesh_, epsilon_);
    const int vertexCount =
        welded.empty() ? 0 : static_cast<int>(*std::max_element(welded.begin(), welded.end())) + 1;
    // Facets around each welded vertex (CSR).
    std::vector<int> start(static_cast<size_t>(vertexCount) + 1, 0), around;
    for (const glm::uvec3& t : mesh_.triangles)
        for (int c = 0; c < 3; ++c) ++start[static_cast<size_t>(welded[t[c]]) + 1];
    for (size_t v = 0; v < static_cast<size_t>(vertexCount); ++v) start[v + 1] += start[v];
    around.resize(static_cast<size_t>(start.back()));
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (size_t f = 0; f < mesh_.triangles.size(); ++f)
        for (int c = 0; c < 3; ++c)
            around[static_cast<size_t>(
                fill[static_cast<size_t>(welded[mesh_.triangles[f][c]])]++)] = static_cast<int>(f);
    neighbourStart_.assign(1, 0);
    std::vector<int> ring;
    for (size_t f = 0; f < mesh_.triangles.size(); ++f) {
        ring.clear();
        for (int c = 0; c < 3; ++c) {
            const auto v = static_cast<size_t>(welded[mesh_.triangles[f][c]]);
            for (int i = start[v]; i < start[v + 1]; ++i)
                if (around[static_cast<size_t>(i)] != static_cast<int>(f))
                    ring.push_back(around[static_cast<size_t>(i)]);
        }
        std::sort(ring.begin(), ring.end());
        ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
        neighbours_.insert(neighbours_.end(), ring.begin(), ring.end());
        neighbourStart_.push_back(static_cast<int>(neighbours_.size()));
    }
}

bool MeshBoundary::facet(int facet, glm::dvec3 (&v)[3], glm::dvec3& normal) const {
    const glm::uvec3 tri = mesh_.triangles[static_cast<size_t>(facet)];
    for (int c = 0; c < 3; ++c) v[c] = glm::dvec3(mesh_.positions[tri[c]]);
    normal = facetNormals_[static_cast<size_t>(facet)];
    return true;
}

std::span<const int> MeshBoundary::facetNeighbours(int facet) const {
    const auto f = static_cast<size_t>(facet);
    return {neighbours_.data() + neighbourStart_[f],
            static_cast<size_t>(neighbourStart_[f + 1] - neighbourStart_[f])};
}

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
