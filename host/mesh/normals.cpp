// ensureNormals (mesh.h): vertex normals of smooth groups split at a crease
// angle, so a hard edge (a cube's) does not tilt the normals of the faces
// beside it towards a light they face away from.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <unordered_map>
#include <utility>

#include "mesh/mesh.h"
#include "mesh/weld.h"
#include "util/error.h"
#include "util/union_find.h"

namespace tsis {

namespace {

constexpr uint32_t kNone = UINT32_MAX;

// Keeps the file's usable normals (normalised); true for each kept one.
std::vector<char> keepFileNormals(Mesh& mesh) {
    std::vector<char> valid(mesh.positions.size(), 0);
    for (size_t i = 0; i < mesh.normals.size(); ++i) {
        const glm::dvec3 v(mesh.normals[i]);
        const double len = glm::length(v);
        if (std::isfinite(len) && len > 1e-20) {
            mesh.normals[i] = glm::vec3(v / len);
            valid[i] = 1;
        }
    }
    return valid;
}

// Corners (3·triangle + k) grouped by welded position: the fan around each
// point of the surface, seams included.
struct Fans {
    std::vector<uint32_t> start;    // per welded id, into corners; one past the end last
    std::vector<uint32_t> corners;  // grouped by welded id
};

Fans fansOf(const Mesh& mesh, const std::vector<uint32_t>& weld) {
    Fans f;
    f.start.assign(mesh.positions.size() + 1, 0);
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++f.start[weld[t[k]] + 1];
    for (size_t i = 1; i < f.start.size(); ++i) f.start[i] += f.start[i - 1];
    f.corners.resize(3 * mesh.triangles.size());
    std::vector<uint32_t> fill(f.start.begin(), f.start.end() - 1);
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            f.corners[fill[weld[mesh.triangles[t][k]]]++] = uint32_t(3 * t + k);
    return f;
}

// Joins the corners of each fan into smooth groups: across an edge of the fan
// whose two faces differ by at most the crease (cosCrease), or all of them
// (smoothAll). A face without a direction (no area) joins the first face it
// shares an edge with, so it neither bridges two groups nor gets a copy.
UnionFind smoothGroups(const Mesh& mesh, const std::vector<uint32_t>& weld, const Fans& fans,
                       const std::vector<glm::dvec3>& unit, double cosCrease, bool smoothAll) {
    UnionFind groups(3 * mesh.triangles.size());
    std::vector<std::pair<uint32_t, uint32_t>> spokes;  // other end of an edge, corner
    std::vector<uint32_t> attached;  // corners of faces without a direction, joined
    for (size_t w = 0; w + 1 < fans.start.size(); ++w) {
        const uint32_t* first = fans.corners.data() + fans.start[w];
        const uint32_t* last = fans.corners.data() + fans.start[w + 1];
        if (last - first < 2) continue;
        if (smoothAll) {
            for (const uint32_t* c = first + 1; c < last; ++c) groups.unite(*first, *c);
            continue;
        }
        spokes.clear();
        for (const uint32_t* c = first; c < last; ++c) {
            const glm::uvec3& tri = mesh.triangles[*c / 3];
            for (int step = 1; step <= 2; ++step) {
                const uint32_t other = weld[tri[(*c % 3 + step) % 3]];
                if (other != w) spokes.emplace_back(other, *c);
            }
        }
        std::sort(spokes.begin(), spokes.end());
        attached.clear();
        for (int pass = 0; pass < 2; ++pass)  // faces with a direction first
            for (size_t i = 0; i < spokes.size(); ++i)
                for (size_t j = i + 1; j < spokes.size() && spokes[j].first == spokes[i].first;
                     ++j) {
                    const uint32_t a = spokes[i].second, b = spokes[j].second;
                    const glm::dvec3 &na = unit[a / 3], &nb = unit[b / 3];
                    const bool flatA = na == glm::dvec3(0.0), flatB = nb == glm::dvec3(0.0);
                    if (pass == 0 && !flatA && !flatB && glm::dot(na, nb) >= cosCrease)
                        groups.unite(a, b);
                    const uint32_t flat = flatA ? a : b;
                    if (pass == 1 && flatA != flatB &&
                        std::find(attached.begin(), attached.end(), flat) == attached.end()) {
                        groups.unite(a, b);
                        attached.push_back(flat);
                    }
                }
    }
    return groups;
}

}  // namespace

void ensureNormals(Mesh& mesh, double creaseDegrees) {
    const size_t n = mesh.positions.size();
    TSIS_CHECK(mesh.normals.empty() || mesh.normals.size() == n);
    TSIS_CHECK(mesh.texcoords.empty() || mesh.texcoords.size() == n);
    TSIS_CHECK(creaseDegrees >= 0 && creaseDegrees <= 180);
    const std::vector<char> valid = keepFileNormals(mesh);
    if (mesh.hasNormals() && std::count(valid.begin(), valid.end(), 1) == std::ptrdiff_t(n)) return;

    // Face normals, area-weighted: the unnormalised cross product is 2·area·n.
    const size_t nt = mesh.triangles.size();
    std::vector<glm::dvec3> cross(nt), unit(nt, glm::dvec3(0.0));
    for (size_t t = 0; t < nt; ++t) {
        const glm::uvec3& tri = mesh.triangles[t];
        const glm::dvec3 a(mesh.positions[tri.x]);
        cross[t] = glm::cross(glm::dvec3(mesh.positions[tri.y]) - a,
                              glm::dvec3(mesh.positions[tri.z]) - a);
        const double len = glm::length(cross[t]);
        if (len > 1e-300 && std::isfinite(len)) unit[t] = cross[t] / len;
    }
    const std::vector<uint32_t> weld = weldPositions(mesh);
    UnionFind groups = smoothGroups(mesh, weld, fansOf(mesh, weld), unit,
                                    std::cos(glm::radians(creaseDegrees)), creaseDegrees >= 180);

    // Each group's sum, and its first face for when the sum cancels (a sheet
    // folded onto itself).
    std::vector<glm::dvec3> sum(3 * nt, glm::dvec3(0.0));
    std::vector<uint32_t> firstFace(3 * nt, kNone);
    for (uint32_t c = 0; c < 3 * nt; ++c) {
        const uint32_t g = groups.find(c);
        sum[g] += cross[c / 3];
        if (firstFace[g] == kNone && unit[c / 3] != glm::dvec3(0.0)) firstFace[g] = c / 3;
    }

    // A vertex keeps the group of its first corner; its corners in other
    // groups move to a copy, one per (vertex, group).
    std::vector<uint32_t> groupOf(n, kNone);
    std::unordered_map<uint64_t, uint32_t> copies;
    for (uint32_t c = 0; c < 3 * nt; ++c) {
        const uint32_t v = mesh.triangles[c / 3][c % 3];
        if (valid[v]) continue;
        const uint32_t g = groups.find(c);
        if (groupOf[v] == kNone) groupOf[v] = g;
        if (groupOf[v] == g) continue;
        const auto [it, added] = copies.try_emplace((uint64_t(g) << 32) | v, 0);
        if (added) {
            it->second = uint32_t(mesh.positions.size());
            mesh.positions.push_back(mesh.positions[v]);
            if (mesh.hasUVs()) mesh.uvs.push_back(mesh.uvs[v]);
            if (mesh.hasTexcoords()) mesh.texcoords.push_back(mesh.texcoords[v]);
            groupOf.push_back(g);
        }
        mesh.triangles[c / 3][c % 3] = it->second;
    }

    mesh.normals.resize(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        if (i < n && valid[i]) continue;
        const uint32_t g = groupOf[i];
        glm::dvec3 v = g == kNone ? glm::dvec3(0.0) : sum[g];
        if (!(glm::length(v) > 1e-300) && g != kNone && firstFace[g] != kNone)
            v = unit[firstFace[g]];
        const double len = glm::length(v);
        // +y for a vertex no triangle uses.
        mesh.normals[i] =
            len > 1e-300 && std::isfinite(len) ? glm::vec3(v / len) : glm::vec3(0.0f, 1.0f, 0.0f);
    }
}

}  // namespace tsis
