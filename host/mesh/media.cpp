#include "mesh/media.h"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/ext/vector_int3_sized.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <numeric>
#include <unordered_map>

namespace tsis {

// A hash grid of the tolerance's cell size, searched in the 27 cells around
// each vertex.
std::vector<int> weldVertices(const Mesh& mesh, double tolerance) {
    std::unordered_map<uint64_t, std::vector<int>> grid;
    auto key = [](glm::i64vec3 c) {
        return (static_cast<uint64_t>(c.x) * 73856093u) ^ (static_cast<uint64_t>(c.y) * 19349663u) ^
               (static_cast<uint64_t>(c.z) * 83492791u);
    };
    std::vector<int> welded(mesh.positions.size());
    std::vector<glm::dvec3> weldedAt;
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::dvec3 p(mesh.positions[i]);
        const glm::i64vec3 cell(glm::floor(p / tolerance));
        int id = -1;
        for (int dx = -1; dx <= 1 && id < 0; ++dx)
            for (int dy = -1; dy <= 1 && id < 0; ++dy)
                for (int dz = -1; dz <= 1 && id < 0; ++dz) {
                    const auto it = grid.find(key(cell + glm::i64vec3(dx, dy, dz)));
                    if (it == grid.end()) continue;
                    for (int w : it->second)
                        if (glm::length(weldedAt[static_cast<size_t>(w)] - p) <= tolerance) {
                            id = w;
                            break;
                        }
                }
        if (id < 0) {
            id = static_cast<int>(weldedAt.size());
            weldedAt.push_back(p);
            grid[key(cell)].push_back(id);
        }
        welded[i] = id;
    }
    return welded;
}

Media findMedia(const Mesh& mesh) {
    Media media;
    media.ofVertex.assign(mesh.positions.size(), 0);
    if (mesh.triangles.empty()) {
        media.count = 1;
        return media;
    }
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // Seams of one solid weld; solids a gap apart (0.5 mm between two cubes
    // of a 50 mm scene) stay apart.
    const double tolerance = 1e-6 * std::max(1e-3, double(glm::length(hi - lo)));
    const std::vector<int> welded = weldVertices(mesh, tolerance);
    std::vector<int> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int v) {
        while (parent[size_t(v)] != v) v = parent[size_t(v)] = parent[size_t(parent[size_t(v)])];
        return v;
    };
    auto unite = [&](int a, int b) {
        a = find(a);
        b = find(b);
        if (a != b) parent[size_t(std::max(a, b))] = std::min(a, b);
    };
    // Vertices at one welded place, then the corners of each triangle.
    std::vector<int> firstAt(mesh.positions.size(), -1);
    for (size_t v = 0; v < welded.size(); ++v) {
        int& first = firstAt[size_t(welded[v])];
        if (first < 0)
            first = int(v);
        else
            unite(first, int(v));
    }
    for (const glm::uvec3& t : mesh.triangles) {
        unite(int(t[0]), int(t[1]));
        unite(int(t[0]), int(t[2]));
    }
    // A piece with an edge of one triangle is open: the open pieces together
    // stay one medium (a slab given as its two faces, a plane), as they were
    // before media.
    std::unordered_map<uint64_t, int> edgeUses;
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const auto a = uint32_t(welded[t[k]]), b = uint32_t(welded[t[(k + 1) % 3]]);
            if (a != b) ++edgeUses[(uint64_t(std::min(a, b)) << 32) | std::max(a, b)];
        }
    std::vector<char> open(mesh.positions.size(), 0);
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const auto a = uint32_t(welded[t[k]]), b = uint32_t(welded[t[(k + 1) % 3]]);
            if (a != b && edgeUses[(uint64_t(std::min(a, b)) << 32) | std::max(a, b)] == 1)
                open[size_t(find(int(t[0])))] = 1;
        }
    std::vector<int> idOfRoot(mesh.positions.size(), -1);
    int openId = -1;
    for (const glm::uvec3& t : mesh.triangles) {
        const size_t root = size_t(find(int(t[0])));
        int& id = idOfRoot[root];
        if (id >= 0) continue;
        if (open[root] && openId >= 0) {
            id = openId;
            continue;
        }
        id = int(media.count++);
        if (open[root]) openId = id;
    }
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const int id = idOfRoot[size_t(find(int(v)))];
        media.ofVertex[v] = id < 0 ? 0u : uint32_t(id);
    }
    return media;
}

}  // namespace tsis
