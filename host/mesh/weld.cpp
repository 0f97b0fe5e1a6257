#include "mesh/weld.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <glm/common.hpp>
#include <glm/ext/vector_int3_sized.hpp>
#include <glm/geometric.hpp>
#include <tuple>
#include <unordered_map>

#include "util/hash.h"
#include "util/union_find.h"

namespace tsis {

namespace {

constexpr double kRelativeTolerance = 1e-6;

bool finite(const glm::dvec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

void finiteBounds(const Mesh& mesh, glm::dvec3& lo, glm::dvec3& hi) {
    lo = glm::dvec3(INFINITY);
    hi = glm::dvec3(-INFINITY);
    for (const glm::vec3& p : mesh.positions)
        if (finite(glm::dvec3(p))) {
            lo = glm::min(lo, glm::dvec3(p));
            hi = glm::max(hi, glm::dvec3(p));
        }
}

}  // namespace

std::vector<uint32_t> weldPositions(const Mesh& mesh) {
    glm::dvec3 lo, hi;
    finiteBounds(mesh, lo, hi);
    const double diagonal = glm::length(hi - lo);
    return weldPositions(
        mesh, diagonal > 0 && std::isfinite(diagonal) ? kRelativeTolerance * diagonal : 1);
}

std::vector<uint32_t> weldPositions(const Mesh& mesh, double tolerance) {
    const size_t n = mesh.positions.size();
    std::vector<uint32_t> weld(n);
    glm::dvec3 lo, hi;
    finiteBounds(mesh, lo, hi);
    const double tol = std::max(tolerance, glm::length(hi - lo) * 1e-6);
    // Cells twice the tolerance wide, counted from the box's corner (under 2²¹
    // a side, so three fit one 64-bit key exactly): a point within tol of p
    // lies, along each axis, in p's cell or the neighbour on the side p is
    // within tol of — 8 cells to search (27 at a half-way point), not 27
    // cells of the tolerance's size (a 1.2M-triangle scan: seconds).
    const double size = 2.0 * tol;
    auto cellKey = [](const glm::i64vec3& c) {
        return (uint64_t(c.x) << 42) | (uint64_t(c.y) << 21) | uint64_t(c.z);
    };
    // Each cell's representatives as a list through `next`, newest first.
    std::unordered_map<uint64_t, uint32_t> newest;
    newest.reserve(n);
    std::vector<uint32_t> next(n, UINT32_MAX);
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3 p(mesh.positions[i]);
        weld[i] = uint32_t(i);
        if (!finite(p)) continue;
        const glm::dvec3 q = (p - lo) / size;
        const glm::i64vec3 cell(glm::floor(q));
        int from[3], to[3];
        for (int k = 0; k < 3; ++k) {
            const double f = q[k] - double(cell[k]);  // [0, 1): tol is 0.5
            from[k] = f * size <= tol * (1 + 1e-9) ? -1 : 0;
            to[k] = (1 - f) * size <= tol * (1 + 1e-9) ? 1 : 0;
        }
        uint32_t found = UINT32_MAX;
        for (int dx = from[0]; dx <= to[0]; ++dx)
            for (int dy = from[1]; dy <= to[1]; ++dy)
                for (int dz = from[2]; dz <= to[2]; ++dz) {
                    const glm::i64vec3 c = cell + glm::i64vec3(dx, dy, dz);
                    if (c.x < 0 || c.y < 0 || c.z < 0) continue;
                    const auto it = newest.find(cellKey(c));
                    if (it == newest.end()) continue;
                    for (uint32_t r = it->second; r != UINT32_MAX; r = next[r])
                        if (r < found && glm::length(glm::dvec3(mesh.positions[r]) - p) <= tol)
                            found = r;
                }
        if (found != UINT32_MAX) {
            weld[i] = found;
        } else {
            const auto [it, added] = newest.try_emplace(cellKey(cell), uint32_t(i));
            if (!added) {
                next[i] = it->second;
                it->second = uint32_t(i);
            }
        }
    }
    return weld;
}

namespace {

// Every triangle's edges between welded positions (a < b, degenerate ones
// left out), sorted: an edge's uses are one run.
struct WeldedEdge {
    uint32_t a, b, triangle;
};
std::vector<WeldedEdge> sortedEdges(const Mesh& mesh, const std::vector<uint32_t>& weld) {
    std::vector<WeldedEdge> edges;
    edges.reserve(3 * mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = weld[mesh.triangles[t][k]], b = weld[mesh.triangles[t][(k + 1) % 3]];
            if (a != b) edges.push_back({std::min(a, b), std::max(a, b), uint32_t(t)});
        }
    std::sort(edges.begin(), edges.end(), [](const WeldedEdge& x, const WeldedEdge& y) {
        return std::tie(x.a, x.b, x.triangle) < std::tie(y.a, y.b, y.triangle);
    });
    return edges;
}

// Calls f(edge) for each edge used by exactly one triangle.
template <typename F>
void forEachBoundaryEdge(const std::vector<WeldedEdge>& edges, F f) {
    for (size_t i = 0; i < edges.size();) {
        size_t j = i + 1;
        while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) ++j;
        if (j - i == 1) f(edges[i]);
        i = j;
    }
}

}  // namespace

size_t boundaryEdges(const Mesh& mesh) {
    size_t boundary = 0;
    forEachBoundaryEdge(sortedEdges(mesh, weldPositions(mesh)),
                        [&](const WeldedEdge&) { ++boundary; });
    return boundary;
}

std::vector<char> trianglesOnBoundary(const Mesh& mesh, const std::vector<uint32_t>& weld) {
    std::vector<char> on(mesh.triangles.size(), 0);
    forEachBoundaryEdge(sortedEdges(mesh, weld), [&](const WeldedEdge& e) { on[e.triangle] = 1; });
    return on;
}

bool closedOutward(const Mesh& mesh) {
    if (mesh.triangles.empty()) return false;
    // Positions by their bits (0 and −0 are two points).
    using Bits = std::array<uint32_t, 3>;
    struct BitsHash {
        size_t operator()(const Bits& b) const { return size_t(fnv1a(b.data(), sizeof b)); }
    };
    std::unordered_map<Bits, uint32_t, BitsHash> idOf;
    idOf.reserve(mesh.positions.size());
    std::vector<uint32_t> id(mesh.positions.size());
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3& p = mesh.positions[v];
        const Bits bits{std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y),
                        std::bit_cast<uint32_t>(p.z)};
        id[v] = idOf.try_emplace(bits, uint32_t(idOf.size())).first->second;
    }
    // Every undirected edge twice, once each way: sorted by (edge, direction).
    std::vector<uint64_t> edges;
    edges.reserve(mesh.triangles.size() * 3);
    // (A triangle with two corners on one point covers nothing: its other
    // two edges would pair with each other.)
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::uvec3 w(id[t.x], id[t.y], id[t.z]);
        if (w.x == w.y || w.y == w.z || w.x == w.z) continue;
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = w[k], b = w[(k + 1) % 3];
            edges.push_back((uint64_t(std::min(a, b)) << 32 | std::max(a, b)) << 1 | (a < b));
        }
    }
    if (edges.empty()) return false;
    std::sort(edges.begin(), edges.end());
    for (size_t i = 0; i < edges.size(); i += 2)
        if (i + 1 >= edges.size() || edges[i] >> 1 != edges[i + 1] >> 1 || (edges[i] & 1) != 0 ||
            (edges[i + 1] & 1) != 1 || (i + 2 < edges.size() && edges[i + 2] >> 1 == edges[i] >> 1))
            return false;
    // Parts (over the welded ids) and each one's signed volume.
    UnionFind parts(idOf.size());
    for (const glm::uvec3& t : mesh.triangles) {
        parts.unite(id[t.x], id[t.y]);
        parts.unite(id[t.x], id[t.z]);
    }
    std::unordered_map<uint32_t, double> volume;
    const glm::dvec3 o(mesh.positions[mesh.triangles[0].x]);
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 a = glm::dvec3(mesh.positions[t.x]) - o,
                         b = glm::dvec3(mesh.positions[t.y]) - o,
                         c = glm::dvec3(mesh.positions[t.z]) - o;
        volume[parts.find(id[t.x])] += glm::dot(a, glm::cross(b, c));
    }
    return std::all_of(volume.begin(), volume.end(), [](const auto& v) { return v.second > 0; });
}

}  // namespace tsis
