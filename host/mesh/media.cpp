#include "mesh/media.h"

#include <algorithm>
#include <numeric>

#include "mesh/weld.h"

namespace tsis {

Media findMedia(const Mesh& mesh) {
    Media media;
    media.ofVertex.assign(mesh.positions.size(), 0);
    if (mesh.triangles.empty()) {
        media.count = 1;
        media.materialOf.assign(1, kNoFileMaterial);
        return media;
    }
    // Seams of one solid weld; solids a gap apart (0.5 mm between two cubes
    // of a 50 mm scene) stay apart.
    const std::vector<uint32_t> welded = weldPositions(mesh);
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
    for (size_t v = 0; v < welded.size(); ++v) unite(int(v), int(welded[v]));
    for (const glm::uvec3& t : mesh.triangles) {
        unite(int(t[0]), int(t[1]));
        unite(int(t[0]), int(t[2]));
    }
    // One piece (the common case): one medium, whether closed or not.
    const int firstRoot = find(int(mesh.triangles[0][0]));
    bool onePiece = true;
    for (const glm::uvec3& t : mesh.triangles)
        if (find(int(t[0])) != firstRoot) {
            onePiece = false;
            break;
        }
    if (onePiece) {
        media.count = 1;
        media.materialOf.assign(1, mesh.materialOf(0));
        return media;
    }
    // A piece with an edge of one triangle is open: the open pieces together
    // stay one medium (a slab given as its two faces, a plane), as they were
    // before media.
    const std::vector<char> onBoundary = trianglesOnBoundary(mesh, welded);
    std::vector<char> open(mesh.positions.size(), 0);
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        if (onBoundary[t]) open[size_t(find(int(mesh.triangles[t][0])))] = 1;
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
        media.materialOf.push_back(mesh.materialOf(size_t(&t - mesh.triangles.data())));
        if (open[root]) openId = id;
    }
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const int id = idOfRoot[size_t(find(int(v)))];
        media.ofVertex[v] = id < 0 ? 0u : uint32_t(id);
    }
    return media;
}

}  // namespace tsis
