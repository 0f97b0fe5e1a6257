// splitFaces: spatially coherent parts of a mesh for parallel segmentation
// (see chart.h).
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <unordered_map>
#include <utility>
#include <vector>

#include "atlas/chart.h"

namespace tsis::atlas {

namespace {

// Gives faces (usable ones) parts first … first+parts−1: cut across the longest
// side of their centroids' bounding box at the face that splits them in the
// ratio of the parts on either side, recursively. Ties on a coordinate go by
// face index, so the cut does not depend on the sort's order of visits.
void bisect(const std::vector<glm::dvec3>& centroid, std::vector<int>::iterator begin,
            std::vector<int>::iterator end, int first, int parts, std::vector<int>& part) {
    if (parts <= 1 || end - begin < 2) {
        for (auto it = begin; it != end; ++it) part[size_t(*it)] = first;
        return;
    }
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (auto it = begin; it != end; ++it) {
        lo = glm::min(lo, centroid[size_t(*it)]);
        hi = glm::max(hi, centroid[size_t(*it)]);
    }
    const glm::dvec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    const int left = parts / 2;
    const auto mid = begin + (end - begin) * left / parts;
    std::nth_element(begin, mid, end, [&](int a, int b) {
        const double ca = centroid[size_t(a)][axis], cb = centroid[size_t(b)][axis];
        return ca < cb || (ca == cb && a < b);
    });
    bisect(centroid, begin, mid, first, left, part);
    bisect(centroid, mid, end, first + left, parts - left, part);
}

}  // namespace

std::vector<int> splitFaces(const Mesh& mesh, const Adjacency& adj, int parts) {
    const size_t n = mesh.triangles.size();
    std::vector<glm::dvec3> centroid(n);
    std::vector<int> faces;
    for (size_t f = 0; f < n; ++f) {
        if (!adj.usable[f]) continue;
        const glm::uvec3 t = mesh.triangles[f];
        centroid[f] = (glm::dvec3(mesh.positions[t.x]) + glm::dvec3(mesh.positions[t.y]) +
                       glm::dvec3(mesh.positions[t.z])) /
                      3.0;
        faces.push_back(int(f));
    }
    std::vector<int> part(n, -1);
    bisect(centroid, faces.begin(), faces.end(), 0, std::max(1, parts), part);

    // A plane cut leaves pieces cut off from their part (a finger whose hand is
    // across the cut): each piece but a part's largest joins the neighbouring
    // part it shares most edges with, so that VSA does not spend a proxy on
    // each. Pieces that touch no other part (a separate component of the mesh)
    // stay.
    for (int round = 0; round < 8; ++round) {
        UnionFind comps{n};
        for (size_t f = 0; f < n; ++f)
            for (int g : adj.across[f])
                if (g >= 0 && part[f] >= 0 && part[size_t(g)] == part[f])
                    comps.unite(uint32_t(f), uint32_t(g));
        std::vector<int> size(n, 0);
        for (size_t f = 0; f < n; ++f)
            if (part[f] >= 0) ++size[comps.find(uint32_t(f))];
        std::vector<int> largest(size_t(std::max(1, parts)), -1);  // part -> its largest piece
        for (size_t f = 0; f < n; ++f) {
            if (part[f] < 0 || comps.find(uint32_t(f)) != f) continue;
            int& l = largest[size_t(part[f])];
            if (l < 0 || size[f] > size[size_t(l)]) l = int(f);
        }
        // Each piece but its part's largest joins the part it borders most.
        const bool moved = moveToMostSharedLabel(
            adj, part, [&](size_t f) { return size_t(comps.find(uint32_t(f))); },
            [&](size_t piece, size_t f) { return int(piece) != largest[size_t(part[f])]; });
        if (!moved) break;
    }
    return part;
}

}  // namespace tsis::atlas
