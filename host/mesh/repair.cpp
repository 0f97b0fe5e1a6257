#include "mesh/repair.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numeric>
#include <tuple>

#include "mesh/parse_util.h"
#include "mesh/weld.h"
#include "util/error.h"

namespace tsis {

namespace {

using meshparse::plural;

void note(const Mesh& mesh, const std::string& what) {
    meshparse::note(mesh.name, what);
}

void validate(const Mesh& mesh) {
    const size_t n = mesh.positions.size();
    TSIS_CHECK(mesh.normals.empty() || mesh.normals.size() == n);
    TSIS_CHECK(mesh.uvs.empty() || mesh.uvs.size() == n);
    TSIS_CHECK(mesh.texcoords.empty() || mesh.texcoords.size() == n);
    TSIS_CHECK(mesh.materialIds.empty() || mesh.materialIds.size() == mesh.triangles.size());
    for (size_t i = 0; i < n; ++i) {
        const glm::vec3& p = mesh.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            fail("mesh '", mesh.name, "': vertex ", i, " has a non-finite coordinate");
    }
    for (size_t i = 0; i < mesh.uvs.size(); ++i)
        if (!std::isfinite(mesh.uvs[i].x) || !std::isfinite(mesh.uvs[i].y))
            fail("mesh '", mesh.name, "': vertex ", i, " has a non-finite texture coordinate");
    for (size_t i = 0; i < mesh.texcoords.size(); ++i)
        if (!std::isfinite(mesh.texcoords[i].x) || !std::isfinite(mesh.texcoords[i].y))
            fail("mesh '", mesh.name, "': vertex ", i, " has a non-finite texture coordinate");
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (mesh.triangles[t][k] >= n)
                fail("mesh '", mesh.name, "': triangle ", t, " uses vertex ", mesh.triangles[t][k],
                     " but there are only ", n, " vertices");
    if (mesh.triangles.empty()) fail("mesh '", mesh.name, "': no triangles");
}

// Folds vertices equal in every attribute (the file's texcoords included: a
// texture seam stays open); returns how many went.
size_t mergeDuplicates(Mesh& mesh) {
    const size_t n = mesh.positions.size();
    // Bit patterns: exact equality, a total order even for NaN normals; +0.0f
    // folds -0.0 (equal as numbers, so equal as vertices).
    auto key = [&](uint32_t i) {
        const glm::vec3 p = mesh.positions[i] + 0.0f;
        const glm::vec3 q = mesh.hasNormals() ? mesh.normals[i] + 0.0f : glm::vec3(0.0f);
        const glm::vec2 w = mesh.hasTexcoords() ? mesh.texcoords[i] + 0.0f : glm::vec2(0.0f);
        auto bits = [](float f) { return std::bit_cast<uint32_t>(f); };
        return std::make_tuple(bits(p.x), bits(p.y), bits(p.z), bits(q.x), bits(q.y), bits(q.z),
                               bits(w.x), bits(w.y));
    };
    std::vector<uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
    std::vector<uint32_t> remap(n);
    size_t merged = 0;
    for (size_t i = 0; i < n; ++i) {
        const uint32_t v = order[i];
        if (i > 0 && key(order[i - 1]) == key(v)) {
            remap[v] = remap[order[i - 1]];
            ++merged;
        } else {
            remap[v] = v;
        }
    }
    if (merged == 0) return 0;
    for (glm::uvec3& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) tri[k] = remap[tri[k]];
    return merged;  // the orphans go in the silent compaction after
}

// Triangle t moved to slot `to` (≤ t) with its file material.
void keepTriangle(Mesh& mesh, size_t t, size_t to) {
    mesh.triangles[to] = mesh.triangles[t];
    if (!mesh.materialIds.empty()) mesh.materialIds[to] = mesh.materialIds[t];
}
void resizeTriangles(Mesh& mesh, size_t count) {
    mesh.triangles.resize(count);
    if (!mesh.materialIds.empty()) mesh.materialIds.resize(count);
}

size_t dropDegenerate(Mesh& mesh) {
    glm::dvec3 lo(mesh.positions[0]), hi(lo);
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    const double diagonal = glm::length(hi - lo);
    const double minArea = 1e-12 * diagonal * diagonal;
    size_t kept = 0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        const bool repeated = tri.x == tri.y || tri.y == tri.z || tri.x == tri.z;
        if (repeated || !(mesh.triangleArea(t) > minArea)) continue;
        keepTriangle(mesh, t, kept++);
    }
    const size_t dropped = mesh.triangles.size() - kept;
    resizeTriangles(mesh, kept);
    return dropped;
}

// Drops every later copy of a triangle with the same corners in the same
// cyclic order ((a,b,c), (b,c,a), (c,a,b)); the first stays where it was. A
// reversed copy (a,c,b) is another face, the back of the first, and stays.
size_t dropDuplicateTriangles(Mesh& mesh) {
    auto canonical = [&](uint32_t t) {
        const glm::uvec3 v = mesh.triangles[t];
        const int k = v.x <= v.y && v.x <= v.z ? 0 : (v.y <= v.z ? 1 : 2);
        return std::make_tuple(v[k], v[(k + 1) % 3], v[(k + 2) % 3]);
    };
    const size_t n = mesh.triangles.size();
    std::vector<uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return canonical(a) < canonical(b); });
    std::vector<char> keep(n, 1);
    size_t dropped = 0;
    for (size_t i = 1; i < n; ++i)
        if (canonical(order[i]) == canonical(order[i - 1])) {
            keep[order[i]] = 0;
            ++dropped;
        }
    if (dropped == 0) return 0;
    size_t kept = 0;
    for (size_t t = 0; t < n; ++t)
        if (keep[t]) keepTriangle(mesh, t, kept++);
    resizeTriangles(mesh, kept);
    return dropped;
}

size_t dropUnreferenced(Mesh& mesh) {
    const size_t n = mesh.positions.size();
    std::vector<uint32_t> remap(n, UINT32_MAX);
    for (const glm::uvec3& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) remap[tri[k]] = 0;
    uint32_t next = 0;
    for (size_t i = 0; i < n; ++i) {
        if (remap[i] == UINT32_MAX) continue;
        remap[i] = next;
        mesh.positions[next] = mesh.positions[i];
        if (mesh.hasNormals()) mesh.normals[next] = mesh.normals[i];
        if (mesh.hasUVs()) mesh.uvs[next] = mesh.uvs[i];
        if (mesh.hasTexcoords()) mesh.texcoords[next] = mesh.texcoords[i];
        ++next;
    }
    if (next == n) return 0;
    mesh.positions.resize(next);
    if (mesh.hasNormals()) mesh.normals.resize(next);
    if (mesh.hasUVs()) mesh.uvs.resize(next);
    if (mesh.hasTexcoords()) mesh.texcoords.resize(next);
    for (glm::uvec3& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) tri[k] = remap[tri[k]];
    return n - next;
}

}  // namespace

EdgeStats edgeStats(const Mesh& mesh) {
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    edges.reserve(3 * mesh.triangles.size());
    for (const glm::uvec3& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = tri[k], b = tri[(k + 1) % 3];
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    std::sort(edges.begin(), edges.end());
    EdgeStats stats;
    for (size_t i = 0; i < edges.size();) {
        size_t j = i + 1;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        ++stats.edges;
        if (j - i == 1) ++stats.boundary;
        if (j - i > 2) ++stats.nonManifold;
        i = j;
    }
    return stats;
}

RepairReport repairMesh(Mesh& mesh) {
    validate(mesh);
    RepairReport report;
    report.unreferencedVertices = dropUnreferenced(mesh);
    if (report.unreferencedVertices)
        note(mesh, concat("removed ", report.unreferencedVertices, " unreferenced ",
                          plural(report.unreferencedVertices, "vertex", "vertices")));
    if (!mesh.hasUVs()) {
        report.mergedVertices = mergeDuplicates(mesh);
        if (report.mergedVertices)
            note(mesh, concat("merged ", report.mergedVertices, " duplicate ",
                              plural(report.mergedVertices, "vertex", "vertices")));
    }
    report.degenerateTriangles = dropDegenerate(mesh);
    if (report.degenerateTriangles)
        note(mesh, concat("removed ", report.degenerateTriangles, " degenerate ",
                          plural(report.degenerateTriangles, "triangle", "triangles")));
    if (mesh.triangles.empty())
        fail("mesh '", mesh.name, "': no triangles left after removing ",
             report.degenerateTriangles, " degenerate ones");
    report.duplicateTriangles = dropDuplicateTriangles(mesh);
    if (report.duplicateTriangles)
        note(mesh, concat("removed ", report.duplicateTriangles, " duplicate ",
                          plural(report.duplicateTriangles, "triangle", "triangles"),
                          " (same corners as an earlier one)"));
    // Vertices left over by merging or used only by degenerate triangles: the
    // notes above already account for them.
    dropUnreferenced(mesh);
    report.nonManifoldEdges = edgeStats(mesh).nonManifold;
    if (report.nonManifoldEdges)
        note(mesh, concat(report.nonManifoldEdges, " non-manifold ",
                          plural(report.nonManifoldEdges, "edge", "edges"),
                          " (shared by more than two triangles); kept"));
    return report;
}

size_t noteIfOpen(const Mesh& mesh) {
    const size_t open = boundaryEdges(mesh);
    if (open)
        note(mesh, concat("not closed (", open, " boundary ", plural(open, "edge", "edges"),
                          "): the dipole assumes a closed solid"));
    return open;
}

}  // namespace tsis
