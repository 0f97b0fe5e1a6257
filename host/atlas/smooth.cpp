// The shape charts are made of: a noisy scan's relief at the scale of its
// triangles defeats segmentation (VSA labels follow the noise) and flattening
// (no small piece maps within the distortion limit), and splitting on made
// tens of thousands of tiny charts. Such a mesh is charted on a smoothed copy
// (same connectivity); the UVs then serve the real surface, whose texels
// carry their own areas (docs/design.md §1, "The texture atlas").
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>

#include "atlas/chart.h"

namespace tsis {
namespace atlas {

namespace {

glm::dvec3 faceNormal(const Mesh& mesh, const glm::uvec3& t) {
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double l = glm::length(n);
    return l > 0 ? n / l : n;
}

}  // namespace

double medianDihedralDegrees(const Mesh& mesh, const Adjacency& adj) {
    std::vector<float> angles;
    angles.reserve(mesh.triangles.size() * 3 / 2);
    std::vector<glm::dvec3> normal(mesh.triangles.size());
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        normal[f] = faceNormal(mesh, mesh.triangles[f]);
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (!adj.usable[f]) continue;
        for (int g : adj.across[f])
            if (g > int(f) && adj.usable[size_t(g)])
                angles.push_back(float(
                    std::acos(std::clamp(glm::dot(normal[f], normal[size_t(g)]), -1.0, 1.0))));
    }
    if (angles.empty()) return 0;
    auto mid = angles.begin() + std::ptrdiff_t(angles.size() / 2);
    std::nth_element(angles.begin(), mid, angles.end());
    return double(*mid) * 180.0 / M_PI;
}

double concaveShareOfSharpEdges(const Mesh& mesh, const Adjacency& adj) {
    const double sharp = std::cos(kRoughDihedralDegrees * M_PI / 180.0);
    size_t edges = 0, concave = 0;
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (!adj.usable[f]) continue;
        const glm::uvec3 t = mesh.triangles[f];
        const glm::dvec3 n = faceNormal(mesh, t);
        for (int e = 0; e < 3; ++e) {
            const int g = adj.across[f][size_t(e)];
            if (g <= int(f) || !adj.usable[size_t(g)]) continue;
            const glm::uvec3 u = mesh.triangles[size_t(g)];
            if (glm::dot(n, faceNormal(mesh, u)) >= sharp) continue;
            // g's corner off the shared edge lies above f's plane: a valley.
            uint32_t far = u.x;
            for (int k = 0; k < 3; ++k)
                if (u[k] != t[e] && u[k] != t[(e + 1) % 3]) far = u[k];
            ++edges;
            concave +=
                glm::dot(n, glm::dvec3(mesh.positions[far]) - glm::dvec3(mesh.positions[t[e]])) > 0;
        }
    }
    return edges ? double(concave) / double(edges) : 0.0;
}

bool looksLikeNoisyScan(const Mesh& mesh, const Adjacency& adj) {
    const size_t usable = size_t(std::count(adj.usable.begin(), adj.usable.end(), 1));
    return usable >= kMinScanFaces && medianDihedralDegrees(mesh, adj) > kRoughDihedralDegrees &&
           concaveShareOfSharpEdges(mesh, adj) >= kMinConcaveShare;
}

std::optional<Mesh> smoothedForCharting(const Mesh& mesh, const Adjacency& adj, int* iterations) {
    int done = 0;
    if (iterations) *iterations = 0;
    if (!looksLikeNoisyScan(mesh, adj)) return std::nullopt;
    Mesh shape = mesh;
    // Each vertex's neighbours through the triangles' edges.
    std::vector<std::vector<uint32_t>> ring(mesh.positions.size());
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            ring[t[k]].push_back(t[(k + 1) % 3]);
            ring[t[k]].push_back(t[(k + 2) % 3]);
        }
    for (auto& r : ring) {
        std::sort(r.begin(), r.end());
        r.erase(std::unique(r.begin(), r.end()), r.end());
    }
    // Taubin's λ|μ steps (1995): smooth without shrinking.
    std::vector<glm::dvec3> p(mesh.positions.begin(), mesh.positions.end()), next(p.size());
    auto step = [&](double factor) {
        for (size_t v = 0; v < p.size(); ++v) {
            if (ring[v].empty()) {
                next[v] = p[v];
                continue;
            }
            glm::dvec3 mean(0.0);
            for (uint32_t u : ring[v]) mean += p[u];
            mean /= double(ring[v].size());
            next[v] = p[v] + factor * (mean - p[v]);
        }
        p.swap(next);
    };
    while (done < kMaxSmoothingIterations) {
        step(0.5);
        step(-0.53);
        ++done;
        if (done % 4 == 0) {
            for (size_t v = 0; v < p.size(); ++v) shape.positions[v] = glm::vec3(p[v]);
            if (medianDihedralDegrees(shape, adj) <= kSmoothDihedralDegrees) break;
        }
    }
    for (size_t v = 0; v < p.size(); ++v) shape.positions[v] = glm::vec3(p[v]);
    if (iterations) *iterations = done;
    return shape;
}

}  // namespace atlas
}  // namespace tsis
