#include "mesh/mesh.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "util/error.h"

namespace tsis {

namespace {

glm::dvec3 dv(const glm::vec3& v) {
    return glm::dvec3(v);
}

}  // namespace

double Mesh::triangleArea(size_t t) const {
    const glm::uvec3& tri = triangles[t];
    const glm::dvec3 a = dv(positions[tri.x]);
    return 0.5 * glm::length(glm::cross(dv(positions[tri.y]) - a, dv(positions[tri.z]) - a));
}

double Mesh::triangleUVArea(size_t t) const {
    const glm::uvec3& tri = triangles[t];
    const glm::dvec2 a(uvs[tri.x]), b(uvs[tri.y]), c(uvs[tri.z]);
    return 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

double Mesh::surfaceArea() const {
    double sum = 0.0;
    for (size_t t = 0; t < triangles.size(); ++t) sum += triangleArea(t);
    return sum;
}

double Mesh::enclosedVolume() const {
    double sum = 0.0;
    for (const glm::uvec3& t : triangles)
        sum += glm::dot(dv(positions[t.x]), glm::cross(dv(positions[t.y]), dv(positions[t.z])));
    return std::abs(sum) / 6.0;
}

Normalization normalizeMesh(Mesh& mesh, double sizeMm) {
    if (!(sizeMm > 0.0) || !std::isfinite(sizeMm))
        fail("mesh '", mesh.name, "': size must be a positive number of mm, got ", sizeMm);
    if (mesh.positions.empty()) fail("mesh '", mesh.name, "': no vertices to normalise");
    glm::dvec3 lo(dv(mesh.positions[0])), hi(lo);
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, dv(p));
        hi = glm::max(hi, dv(p));
    }
    const double diagonal = glm::length(hi - lo);
    if (!(diagonal > 0.0) || !std::isfinite(diagonal))
        fail("mesh '", mesh.name, "': bounding box has zero or non-finite extent (diagonal ",
             diagonal, ")");
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double scale = sizeMm / diagonal;
    for (glm::vec3& p : mesh.positions) p = glm::vec3((dv(p) - centre) * scale);
    return {centre, scale};
}

void ensureNormals(Mesh& mesh) {
    const size_t n = mesh.positions.size();
    TSIS_CHECK(mesh.normals.empty() || mesh.normals.size() == n);

    // Keep the file's normals that are usable; the rest come from the faces.
    std::vector<char> valid(n, 0);
    size_t validCount = 0;
    if (mesh.hasNormals()) {
        for (size_t i = 0; i < n; ++i) {
            const glm::dvec3 v = dv(mesh.normals[i]);
            const double len = glm::length(v);
            if (std::isfinite(len) && len > 1e-20) {
                mesh.normals[i] = glm::vec3(v / len);
                valid[i] = 1;
                ++validCount;
            }
        }
        if (validCount == n) return;
    }

    // Area weighting: the unnormalised cross product is 2·area·n.
    std::vector<glm::dvec3> sum(n, glm::dvec3(0.0));
    std::vector<glm::dvec3> firstFace(n, glm::dvec3(0.0));
    for (const glm::uvec3& tri : mesh.triangles) {
        const glm::dvec3 a = dv(mesh.positions[tri.x]);
        const glm::dvec3 c =
            glm::cross(dv(mesh.positions[tri.y]) - a, dv(mesh.positions[tri.z]) - a);
        for (int k = 0; k < 3; ++k) {
            sum[tri[k]] += c;
            if (firstFace[tri[k]] == glm::dvec3(0.0)) firstFace[tri[k]] = c;
        }
    }
    mesh.normals.resize(n);
    for (size_t i = 0; i < n; ++i) {
        if (valid[i]) continue;
        // Opposite faces can cancel (a sheet folded onto itself): fall back to
        // one face's normal, then to +y for a vertex no triangle uses.
        glm::dvec3 v = sum[i];
        if (!(glm::length(v) > 1e-300)) v = firstFace[i];
        const double len = glm::length(v);
        mesh.normals[i] =
            len > 1e-300 && std::isfinite(len) ? glm::vec3(v / len) : glm::vec3(0.0f, 1.0f, 0.0f);
    }
}

}  // namespace tsis
