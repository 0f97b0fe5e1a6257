#include "mesh/lod.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <limits>
#include <unordered_map>
#include <vector>

#include "util/error.h"

namespace tsis {

MeshLod clusterLod(const Mesh& mesh, float cellMm) {
    TSIS_CHECK(cellMm > 0 && std::isfinite(cellMm));
    MeshLod lod;
    if (mesh.positions.empty()) return lod;
    glm::vec3 lo(std::numeric_limits<float>::max());
    for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p);
    // 21 bits a coordinate: a grid of 2M cells a side, more than any mesh
    // whose triangles are worth clustering.
    auto cellKey = [&](const glm::vec3& p) {
        const glm::vec3 c = glm::floor((p - lo) / cellMm);
        uint64_t key = 0;
        for (int k = 0; k < 3; ++k)
            key = key << 21 | uint64_t(std::clamp(c[k], 0.0f, float((1 << 21) - 1)));
        return key;
    };
    std::unordered_map<uint64_t, uint32_t> clusterOf;
    clusterOf.reserve(mesh.positions.size() / 2);
    std::vector<uint32_t> cluster(mesh.positions.size());
    std::vector<glm::dvec3> sum;
    std::vector<uint32_t> count;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const auto [it, added] =
            clusterOf.try_emplace(cellKey(mesh.positions[v]), uint32_t(sum.size()));
        if (added) {
            sum.emplace_back(0.0);
            count.push_back(0);
        }
        cluster[v] = it->second;
        sum[it->second] += glm::dvec3(mesh.positions[v]);
        ++count[it->second];
    }
    lod.mesh.name = mesh.name + " (lod)";
    lod.mesh.positions.resize(sum.size());
    for (size_t c = 0; c < sum.size(); ++c)
        lod.mesh.positions[c] = glm::vec3(sum[c] / double(count[c]));
    for (size_t v = 0; v < mesh.positions.size(); ++v)
        lod.deviationMm = std::max(
            lod.deviationMm, glm::distance(mesh.positions[v], lod.mesh.positions[cluster[v]]));

    // Triangles on three distinct cells, each set of cells once (a thin fold
    // collapses to two coincident triangles; one of them draws the depth).
    std::vector<std::pair<std::array<uint32_t, 3>, uint32_t>> keyed;
    keyed.reserve(mesh.triangles.size() / 2);
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::uvec3 c(cluster[t.x], cluster[t.y], cluster[t.z]);
        if (c.x == c.y || c.y == c.z || c.x == c.z) continue;
        std::array<uint32_t, 3> sorted{c.x, c.y, c.z};
        std::sort(sorted.begin(), sorted.end());
        keyed.push_back({sorted, uint32_t(lod.mesh.triangles.size())});
        lod.mesh.triangles.push_back(c);
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<glm::uvec3> kept;
    kept.reserve(keyed.size());
    for (size_t i = 0; i < keyed.size(); ++i)
        if (i == 0 || keyed[i].first != keyed[i - 1].first)
            kept.push_back(lod.mesh.triangles[keyed[i].second]);
    lod.mesh.triangles = std::move(kept);
    return lod;
}

float lodCellForBudget(const Mesh& mesh, size_t triangles) {
    TSIS_CHECK(triangles > 0);
    return static_cast<float>(std::sqrt(2.0 * mesh.surfaceArea() / double(triangles)));
}

}  // namespace tsis
