#include "render/surface_points.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <mutex>
#include <unordered_map>

#include "physics/fresnel.h"
#include "render/ray_caster.h"
#include "render/renderer.h"
#include "util/error.h"
#include "util/parallel.h"
#include "util/progress.h"
#include "util/timer.h"

namespace tsis {

namespace {

// Offset of the shadow segment's start above the surface, as a fraction of the
// mesh's bounding-box diagonal: far above float rounding of the positions
// (~1e-7 of the size), far below any feature the dipole resolves.
constexpr double kShadowOffset = 1e-4;

template <typename T>
void hashValue(uint64_t& h, const T& v) {
    const auto* p = reinterpret_cast<const unsigned char*>(&v);
    for (size_t i = 0; i < sizeof(T); ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
}

double boundingDiagonal(const Mesh& mesh) {
    if (mesh.positions.empty()) return 0.0;
    glm::dvec3 lo(mesh.positions[0]), hi(mesh.positions[0]);
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    return glm::length(hi - lo);
}

}  // namespace

double smallestMeanFreePath(const Material& m) {
    const glm::dvec3 sigmaT = m.sigmaSPrime + m.sigmaA;
    return 1.0 / std::max({sigmaT.x, sigmaT.y, sigmaT.z});
}

std::vector<SurfacePoint> placeSurfacePoints(const Mesh& mesh, double spacing) {
    TSIS_CHECK(spacing > 0.0 && std::isfinite(spacing));
    TSIS_CHECK_EQ(mesh.normals.size(), mesh.positions.size());
    // k per triangle first, so the output is allocated once.
    std::vector<uint32_t> k(mesh.triangles.size());
    size_t total = 0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3& tri = mesh.triangles[t];
        const glm::dvec3 a(mesh.positions[tri.x]), b(mesh.positions[tri.y]), c(mesh.positions[tri.z]);
        const double longest =
            std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
        const double kt = std::max(1.0, std::ceil(longest / spacing));
        if (kt > 65535.0)
            fail("sample spacing ", spacing, " mm is too fine for a triangle of edge ", longest,
                 " mm of mesh '", mesh.name, "' (over 4e9 points); use a larger --spacing");
        k[t] = static_cast<uint32_t>(kt);
        total += static_cast<size_t>(k[t]) * k[t];
    }
    std::vector<SurfacePoint> points;
    points.reserve(total);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3& tri = mesh.triangles[t];
        const glm::dvec3 p[3] = {glm::dvec3(mesh.positions[tri.x]), glm::dvec3(mesh.positions[tri.y]),
                                 glm::dvec3(mesh.positions[tri.z])};
        const glm::dvec3 n[3] = {glm::dvec3(mesh.normals[tri.x]), glm::dvec3(mesh.normals[tri.y]),
                                 glm::dvec3(mesh.normals[tri.z])};
        const double kt = k[t];
        const float area = static_cast<float>(mesh.triangleArea(t) / (kt * kt));
        // Barycentric (u, v) of p[1], p[2]; centroids of the "up" sub-triangles
        // at ((i + 1/3)/k, (j + 1/3)/k), of the "down" ones at ((i + 2/3)/k, (j + 2/3)/k).
        auto add = [&](double u, double v) {
            const double w = 1.0 - u - v;
            SurfacePoint s;
            s.position = glm::vec3(w * p[0] + u * p[1] + v * p[2]);
            const glm::dvec3 nn = w * n[0] + u * n[1] + v * n[2];
            const double len = glm::length(nn);
            s.normal = len > 0 ? glm::vec3(nn / len) : glm::vec3(0.0f);
            s.area = area;
            points.push_back(s);
        };
        for (uint32_t i = 0; i < k[t]; ++i)
            for (uint32_t j = 0; i + j < k[t]; ++j) {
                add((i + 1.0 / 3.0) / kt, (j + 1.0 / 3.0) / kt);
                if (i + j + 1 < k[t]) add((i + 2.0 / 3.0) / kt, (j + 2.0 / 3.0) / kt);
            }
    }
    TSIS_CHECK_EQ(points.size(), total);
    return points;
}

glm::dvec3 irradianceAt(const glm::dvec3& x, const glm::dvec3& n, const std::vector<Light>& lights,
                        double eta, const RayCaster& rays, double offset, double reach) {
    glm::dvec3 e(0.0);
    const glm::dvec3 start = x + offset * n;
    for (const Light& light : lights) {
        glm::dvec3 l, end;
        double falloff = 1.0;
        if (light.type == Light::Type::Point) {
            const glm::dvec3 d = glm::dvec3(light.vec) - x;
            const double d2 = glm::dot(d, d);
            if (d2 <= 0.0) continue;
            l = d / std::sqrt(d2);
            falloff = 1.0 / d2;
            end = glm::dvec3(light.vec);
        } else {
            l = -glm::normalize(glm::dvec3(light.vec));
            end = start + reach * l;
        }
        const double cosI = glm::dot(n, l);
        if (cosI <= 0.0) continue;
        if (light.shadows && !rays.segmentClear(start, end)) continue;
        e += glm::dvec3(light.rgb) * (fresnelTransmittance(eta, std::min(1.0, cosI)) * cosI * falloff);
    }
    return e;
}

void computeIrradiance(std::vector<SurfacePoint>& points, const std::vector<Light>& lights,
                       double eta, const RayCaster& rays, double offset, double reach,
                       Progress* progress) {
    std::atomic<size_t> done{0};
    std::mutex progressMutex;
    parallelFor(points.size(), 4096, [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            SurfacePoint& s = points[i];
            s.irradiance = glm::vec3(irradianceAt(glm::dvec3(s.position), glm::dvec3(s.normal),
                                                  lights, eta, rays, offset, reach));
        }
        const size_t d = done += end - begin;
        // Progress is not thread-safe; whoever gets the lock draws.
        if (progress && progressMutex.try_lock()) {
            progress->update(static_cast<long long>(d));
            progressMutex.unlock();
        }
    });
}

std::vector<SurfacePoint> poissonThin(const std::vector<SurfacePoint>& points, double radius) {
    TSIS_CHECK(radius > 0.0 && std::isfinite(radius));
    // Hash grid of cell `radius`: the neighbours closer than radius are in the 27 cells around.
    auto cellOf = [&](const glm::vec3& p) {
        return glm::ivec3(glm::floor(glm::dvec3(p) / radius));
    };
    auto keyOf = [](const glm::ivec3& c) {
        return (static_cast<uint64_t>(static_cast<uint32_t>(c.x) & 0x1fffff) << 42) |
               (static_cast<uint64_t>(static_cast<uint32_t>(c.y) & 0x1fffff) << 21) |
               (static_cast<uint64_t>(static_cast<uint32_t>(c.z) & 0x1fffff));
    };
    std::unordered_map<uint64_t, std::vector<uint32_t>> grid;
    std::vector<uint32_t> kept;
    const float r2 = static_cast<float>(radius * radius);
    // The nearest kept point closer than radius with a compatible normal, or -1.
    auto nearestKept = [&](const SurfacePoint& s) {
        const glm::ivec3 c = cellOf(s.position);
        long best = -1;
        float bestD2 = r2;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    auto it = grid.find(keyOf(c + glm::ivec3(dx, dy, dz)));
                    if (it == grid.end()) continue;
                    for (uint32_t k : it->second) {
                        const glm::vec3 d = points[kept[k]].position - s.position;
                        const float d2 = glm::dot(d, d);
                        if (d2 < bestD2 && glm::dot(points[kept[k]].normal, s.normal) > 0.0f) {
                            bestD2 = d2;
                            best = k;
                        }
                    }
                }
        return best;
    };
    for (uint32_t i = 0; i < points.size(); ++i)
        if (nearestKept(points[i]) < 0) {
            grid[keyOf(cellOf(points[i].position))].push_back(static_cast<uint32_t>(kept.size()));
            kept.push_back(i);
        }
    // Merge in double: a kept point may collect many small triangles.
    std::vector<double> area(kept.size(), 0.0);
    std::vector<glm::dvec3> flux(kept.size(), glm::dvec3(0.0));
    for (const SurfacePoint& s : points) {
        const long k = nearestKept(s);
        TSIS_CHECK_GE(k, 0);  // a point was dropped only because one was near
        area[k] += s.area;
        flux[k] += glm::dvec3(s.irradiance) * static_cast<double>(s.area);
    }
    std::vector<SurfacePoint> out(kept.size());
    for (size_t k = 0; k < kept.size(); ++k) {
        out[k] = points[kept[k]];
        out[k].area = static_cast<float>(area[k]);
        out[k].irradiance = area[k] > 0 ? glm::vec3(flux[k] / area[k]) : glm::vec3(0.0f);
    }
    return out;
}

bool SurfaceSampleCache::update(const Scene& scene, double spacing, const std::string& label) {
    uint64_t key = meshHash(scene.mesh);
    for (const Light& l : scene.lights) {
        hashValue(key, l.type);
        hashValue(key, l.vec);
        hashValue(key, l.rgb);
        hashValue(key, l.shadows);
    }
    hashValue(key, scene.material.eta);
    hashValue(key, spacing);
    if (valid_ && key == key_) return false;
    Timer t;
    points_ = placeSurfacePoints(scene.mesh, spacing);
    {
        const RayCaster rays(scene.mesh);
        const double diagonal = boundingDiagonal(scene.mesh);
        Progress progress(label + ": irradiance at " + std::to_string(points_.size()) + " points",
                          static_cast<long long>(points_.size()));
        computeIrradiance(points_, scene.lights, scene.material.eta, rays, kShadowOffset * diagonal,
                          2.0 * diagonal + 1.0, &progress);
    }
    key_ = key;
    valid_ = true;
    buildMs_ = t.ms();
    return true;
}

}  // namespace tsis
