#include "mesh/mesh.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include "util/error.h"

namespace tsis {

uint32_t Mesh::materialOf(size_t t) const {
    return materialIds.empty() ? kNoFileMaterial : materialIds[t];
}

namespace {

glm::dvec3 dv(const glm::vec3& v) {
    return glm::dvec3(v);
}

// sin and cos of an angle in degrees; exact at multiples of 90° (a cube turned
// by 90° stays axis-aligned bit for bit, and so does its atlas cache key).
glm::dvec2 sinCosDegrees(double degrees) {
    const double r = std::fmod(degrees, 360.0);  // exact
    const double quarter = std::round(r / 90.0);
    if (r == 90.0 * quarter) {
        const int q = ((int(quarter) % 4) + 4) % 4;
        constexpr double kSin[4] = {0, 1, 0, -1};
        return {kSin[q], kSin[(q + 1) % 4]};
    }
    const double a = glm::radians(r);
    return {std::sin(a), std::cos(a)};
}

// The bounding box's corners, the mesh not empty.
void bounds(const Mesh& mesh, glm::dvec3& lo, glm::dvec3& hi) {
    lo = hi = dv(mesh.positions[0]);
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, dv(p));
        hi = glm::max(hi, dv(p));
    }
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

double boundingDiagonal(const Mesh& mesh) {
    if (mesh.positions.empty()) return 0;
    glm::dvec3 lo, hi;
    bounds(mesh, lo, hi);
    return glm::length(hi - lo);
}

Normalization normalizationOf(const Mesh& mesh, double sizeMm) {
    if (!(sizeMm > 0.0) || !std::isfinite(sizeMm))
        fail("mesh '", mesh.name, "': size must be a positive number of mm, got ", sizeMm);
    if (mesh.positions.empty()) fail("mesh '", mesh.name, "': no vertices to normalise");
    glm::dvec3 lo, hi;
    bounds(mesh, lo, hi);
    const double diagonal = glm::length(hi - lo);
    if (!(diagonal > 0.0) || !std::isfinite(diagonal))
        fail("mesh '", mesh.name, "': bounding box has zero or non-finite extent (diagonal ",
             diagonal, ")");
    return {0.5 * (lo + hi), sizeMm / diagonal};
}

Normalization normalizeMesh(Mesh& mesh, double sizeMm) {
    const Normalization n = normalizationOf(mesh, sizeMm);
    for (glm::vec3& p : mesh.positions) p = glm::vec3((dv(p) - n.centre) * n.scale);
    return n;
}

glm::dmat3 meshRotation(const glm::dvec3& degrees, bool zUp) {
    // Columns are the images of the axes.
    using V = glm::dvec3;
    auto aboutX = [](glm::dvec2 sc) {
        return glm::dmat3(V(1, 0, 0), V(0, sc.y, sc.x), V(0, -sc.x, sc.y));
    };
    auto aboutY = [](glm::dvec2 sc) {
        return glm::dmat3(V(sc.y, 0, -sc.x), V(0, 1, 0), V(sc.x, 0, sc.y));
    };
    auto aboutZ = [](glm::dvec2 sc) {
        return glm::dmat3(V(sc.y, sc.x, 0), V(-sc.x, sc.y, 0), V(0, 0, 1));
    };
    const glm::dmat3 up = zUp ? aboutX(sinCosDegrees(-90)) : glm::dmat3(1.0);
    return aboutZ(sinCosDegrees(degrees.z)) * aboutY(sinCosDegrees(degrees.y)) *
           aboutX(sinCosDegrees(degrees.x)) * up;
}

glm::dvec3 rotateMesh(Mesh& mesh, const glm::dmat3& rotation) {
    if (rotation == glm::dmat3(1.0) || mesh.positions.empty()) return glm::dvec3(0.0);
    glm::dvec3 lo, hi;
    bounds(mesh, lo, hi);
    const glm::dvec3 centre = 0.5 * (lo + hi);
    for (glm::vec3& p : mesh.positions) p = glm::vec3(centre + rotation * (dv(p) - centre));
    for (glm::vec3& n : mesh.normals) n = glm::vec3(rotation * dv(n));
    return centre;
}

}  // namespace tsis
