#include "render/env_light.h"

#include <cmath>

#include "mesh/mesh.h"
#include "physics/fresnel.h"
#include "util/parallel.h"
#include "volumetric/mesh_boundary.h"

namespace tsis {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A hash to [0, 1) (PCG-style), so directions depend on the seed only.
double hashUnit(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return (x >> 8) * (1.0 / 16777216.0);
}

}  // namespace

void visibleDirections(const MeshBoundary& mesh, const glm::dvec3& x, const glm::dvec3& n,
                       double offset, int strata, uint32_t seed,
                       const std::function<void(const glm::dvec3&, double)>& f) {
    // An orthonormal frame about n (Duff et al. 2017).
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    const glm::dvec3 t(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    const glm::dvec3 s(b, sign + n.y * n.y * a, -n.y);
    const glm::dvec3 origin = x + offset * n;
    const double rotate = hashUnit(seed * 2654435761u + 1u);
    uint32_t k = seed * 747796405u;
    for (int i = 0; i < strata; ++i)
        for (int j = 0; j < strata; ++j) {
            const double u1 = (i + hashUnit(++k)) / strata, u2 = (j + hashUnit(++k)) / strata;
            const double r = std::sqrt(u1), phi = 2.0 * kPi * (u2 + rotate);
            const double cosT = std::sqrt(std::max(0.0, 1.0 - u1));
            const glm::dvec3 w = t * (r * std::cos(phi)) + s * (r * std::sin(phi)) + n * cosT;
            SurfaceHit hit;
            if (mesh.intersect(origin, w, 1e30, hit)) continue;
            f(w, cosT);
        }
}

EnvTransfer::EnvTransfer() = default;
EnvTransfer::~EnvTransfer() = default;

bool EnvTransfer::update(uint64_t key, const Mesh& mesh, int resolution, double eta,
                         const std::vector<float>& positions, const std::vector<float>& normals) {
    if (key == key_ && !texels_.empty()) return false;
    const MeshBoundary boundary(mesh);
    glm::dvec3 lo(1e30), hi(-1e30);
    for (const glm::vec3& v : mesh.positions) {
        lo = glm::min(lo, glm::dvec3(v));
        hi = glm::max(hi, glm::dvec3(v));
    }
    const double offset = 1e-4 * glm::length(hi - lo);
    resolution_ = resolution;
    texels_.clear();
    const size_t count = static_cast<size_t>(resolution) * resolution;
    for (size_t i = 0; i < count; ++i)
        if (positions[i * 4 + 3] != 0.0f) texels_.push_back(static_cast<uint32_t>(i));
    // Rays from one texel of each kTransferBlock² block stand for the block's
    // texels that lie near it (one chart): visibility of a smooth sky varies
    // over a diffusion length, many texels across. Texels of another chart
    // (an atlas seam in the block) get their own.
    std::vector<int32_t> owner(count, -1);  // texel → the texel whose rays it uses
    std::vector<uint32_t> traced;
    const int b = kTransferBlock;
    for (int by = 0; by < resolution; by += b)
        for (int bx = 0; bx < resolution; bx += b) {
            const size_t blockStart = traced.size();
            for (int y = by; y < std::min(resolution, by + b); ++y)
                for (int x = bx; x < std::min(resolution, bx + b); ++x) {
                    const size_t i = static_cast<size_t>(y) * resolution + x;
                    if (positions[i * 4 + 3] == 0.0f) continue;
                    for (size_t k = blockStart; k < traced.size(); ++k) {
                        const size_t r = traced[k];
                        const glm::vec3 d(positions[i * 4] - positions[r * 4],
                                          positions[i * 4 + 1] - positions[r * 4 + 1],
                                          positions[i * 4 + 2] - positions[r * 4 + 2]);
                        const float near = 2.0f * b * std::sqrt(normals[r * 4 + 3]);
                        if (glm::dot(d, d) <= near * near) {
                            owner[i] = static_cast<int32_t>(r);
                            break;
                        }
                    }
                    if (owner[i] < 0) {
                        owner[i] = static_cast<int32_t>(i);
                        traced.push_back(static_cast<uint32_t>(i));
                    }
                }
        }
    std::vector<float> own(traced.size() * kEnvShCount, 0.0f);
    const double weight = kPi / (kTransferStrata * kTransferStrata);
    parallelFor(traced.size(), 64, [&](size_t begin, size_t end) {
        for (size_t t = begin; t < end; ++t) {
            const size_t i = traced[t];
            const glm::dvec3 x(positions[i * 4], positions[i * 4 + 1], positions[i * 4 + 2]);
            glm::dvec3 n(normals[i * 4], normals[i * 4 + 1], normals[i * 4 + 2]);
            if (glm::length(n) == 0.0) continue;
            n = glm::normalize(n);
            ShCoefficients sum{};
            visibleDirections(boundary, x, n, offset, kTransferStrata, static_cast<uint32_t>(i),
                              [&](const glm::dvec3& w, double cosT) {
                                  const ShCoefficients y = shBasis(w);
                                  const double ft = fresnelTransmittance(eta, cosT);
                                  for (int k = 0; k < kEnvShCount; ++k) sum[k] += ft * y[k];
                              });
            for (int k = 0; k < kEnvShCount; ++k)
                own[t * kEnvShCount + k] = static_cast<float>(sum[k] * weight);
        }
    });
    std::vector<int32_t> slot(count, -1);
    for (size_t t = 0; t < traced.size(); ++t) slot[traced[t]] = static_cast<int32_t>(t);
    ownerSlot_.resize(texels_.size());
    for (size_t t = 0; t < texels_.size(); ++t)
        ownerSlot_[t] = static_cast<uint32_t>(slot[static_cast<size_t>(owner[texels_[t]])]);
    transfer_ = std::move(own);
    traced_ = traced.size();
    key_ = key;
    return true;
}

std::vector<float> EnvTransfer::irradiance(const Environment& env) const {
    const std::array<glm::dvec3, kEnvShCount> l = env.worldSh();
    std::array<glm::vec3, kEnvShCount> lf;
    for (int k = 0; k < kEnvShCount; ++k) lf[k] = glm::vec3(l[k]);
    // One dot product per traced texel; its block's texels take its E.
    std::vector<glm::vec3> traced(traced_);
    parallelFor(traced_, 4096, [&](size_t begin, size_t end) {
        for (size_t t = begin; t < end; ++t) {
            glm::vec3 e(0.0f);
            const float* c = &transfer_[t * kEnvShCount];
            for (int k = 0; k < kEnvShCount; ++k) e += c[k] * lf[k];
            traced[t] = glm::max(e, glm::vec3(0.0f));
        }
    });
    std::vector<float> out(static_cast<size_t>(resolution_) * resolution_ * 4, 0.0f);
    for (size_t t = 0; t < texels_.size(); ++t) {
        const glm::vec3& e = traced[ownerSlot_[t]];
        float* o = &out[static_cast<size_t>(texels_[t]) * 4];
        o[0] = e.x;
        o[1] = e.y;
        o[2] = e.z;
    }
    return out;
}

void addEnvironmentIrradiance(std::vector<SurfacePoint>& points, const Scene& scene,
                              double offset) {
    if (!scene.env) return;
    const MeshBoundary boundary(scene.mesh);
    const double eta = scene.material.eta;
    const double weight = kPi / (kReferenceEnvStrata * kReferenceEnvStrata);
    parallelFor(points.size(), 64, [&](size_t begin, size_t end) {
        for (size_t p = begin; p < end; ++p) {
            SurfacePoint& sp = points[p];
            glm::dvec3 e(0.0);
            visibleDirections(boundary, glm::dvec3(sp.position), glm::dvec3(sp.normal), offset,
                              kReferenceEnvStrata, static_cast<uint32_t>(p),
                              [&](const glm::dvec3& w, double cosT) {
                                  e += scene.env.radiance(w) * fresnelTransmittance(eta, cosT);
                              });
            sp.irradiance += glm::vec3(e * weight);
        }
    });
}

}  // namespace tsis
