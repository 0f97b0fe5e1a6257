#include "mesh/builtin.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "util/error.h"

namespace tsis {

namespace {

constexpr double kPi = std::numbers::pi;

// Adds a grid of (rows+1)×(cols+1) vertices' triangles, two per cell, wound
// so that (next row − here) × (next column − here) is the front side.
void addGridTriangles(Mesh& mesh, uint32_t base, uint32_t rows, uint32_t cols) {
    const uint32_t stride = cols + 1;
    for (uint32_t i = 0; i < rows; ++i)
        for (uint32_t j = 0; j < cols; ++j) {
            const uint32_t a = base + i * stride + j, b = a + stride, c = b + 1, d = a + 1;
            mesh.triangles.emplace_back(a, b, c);
            mesh.triangles.emplace_back(a, c, d);
        }
}

}  // namespace

// UV sphere, 120 slices × 120 stacks uniform in the polar angle θ. UVs are
// equal-area (Archimedes: v = (1 − cos θ)/2 makes A3D/AUV ≈ 4π everywhere), the
// seam column is duplicated, and each pole is one vertex per slice so its
// triangles do not fold in UV space.
Mesh builtinSphere() {
    constexpr uint32_t slices = 120, stacks = 120;
    Mesh m;
    m.name = "builtin:sphere";
    auto add = [&](double theta, double phi, glm::dvec2 uv) {
        const glm::dvec3 p(std::sin(theta) * std::cos(phi), std::cos(theta),
                           -std::sin(theta) * std::sin(phi));
        m.positions.emplace_back(p);
        m.normals.emplace_back(p);
        m.uvs.emplace_back(uv);
    };
    // North pole fan, rings 1 … stacks-1 (with the seam twice), south pole fan.
    for (uint32_t j = 0; j < slices; ++j) add(0.0, 0.0, {(j + 0.5) / slices, 0.0});
    const uint32_t ring0 = static_cast<uint32_t>(m.positions.size());
    for (uint32_t i = 1; i < stacks; ++i) {
        const double theta = kPi * i / stacks;
        for (uint32_t j = 0; j <= slices; ++j)
            add(theta, 2.0 * kPi * j / slices, {double(j) / slices, (1.0 - std::cos(theta)) / 2});
    }
    const uint32_t south = static_cast<uint32_t>(m.positions.size());
    for (uint32_t j = 0; j < slices; ++j) add(kPi, 0.0, {(j + 0.5) / slices, 1.0});
    // The pole vertex sits exactly on the axis whatever φ says.
    for (uint32_t j = 0; j < slices; ++j) {
        m.positions[j] = m.normals[j] = {0.0f, 1.0f, 0.0f};
        m.positions[south + j] = m.normals[south + j] = {0.0f, -1.0f, 0.0f};
    }

    // With φ growing to −z, (next ring) × (next column) points outward.
    const uint32_t stride = slices + 1;
    for (uint32_t j = 0; j < slices; ++j) m.triangles.emplace_back(j, ring0 + j, ring0 + j + 1);
    addGridTriangles(m, ring0, stacks - 2, slices);
    const uint32_t last = ring0 + (stacks - 2) * stride;
    for (uint32_t j = 0; j < slices; ++j)
        m.triangles.emplace_back(last + j, south + j, last + j + 1);
    return m;
}

// 32×32 quads on [−½, ½]² in the xz-plane, front +y; u = x + ½, v = z + ½ exactly.
Mesh builtinPlane() {
    constexpr uint32_t n = 32;
    Mesh m;
    m.name = "builtin:plane";
    // Rows along +z, columns along +x: z × x = +y, the front.
    for (uint32_t i = 0; i <= n; ++i)
        for (uint32_t j = 0; j <= n; ++j) {
            const double u = double(j) / n, v = double(i) / n;
            m.positions.emplace_back(u - 0.5, 0.0, v - 0.5);
            m.normals.emplace_back(0.0f, 1.0f, 0.0f);
            m.uvs.emplace_back(u, v);
        }
    addGridTriangles(m, 0, n, n);
    return m;
}

// The default scene, a "tapered torus": a ring (radius 1, in the xy-plane)
// whose tube is thin at the top (0.08: glows when back-lit) and thick at the
// bottom (0.42: local blur), with a few gentle ridges on the thick part for
// surface detail. One UV chart: u along the ring, v around the tube.
Mesh builtinDefault() {
    constexpr uint32_t ring = 256, tube = 96;  // 49,152 triangles
    constexpr double R = 1.0, rThin = 0.08, rThick = 0.42;
    auto surface = [&](double phi, double psi) {
        const double s = 0.5 * (1.0 - std::sin(phi));  // 0 at the top, 1 at the bottom
        const double ridges = 0.06 * std::sin(7.0 * phi) + 0.03 * std::sin(5.0 * psi + phi);
        const double r = (rThin + (rThick - rThin) * s) * (1.0 + s * s * ridges);
        const glm::dvec3 out(std::cos(phi), std::sin(phi), 0.0);
        return R * out + r * (std::cos(psi) * out + std::sin(psi) * glm::dvec3(0, 0, 1));
    };
    Mesh m;
    m.name = "builtin:default";
    const double h = 1e-6;
    for (uint32_t i = 0; i <= ring; ++i)
        for (uint32_t j = 0; j <= tube; ++j) {
            // Seam vertices repeat the angle 0 exactly so both copies coincide.
            const double phi = 2.0 * kPi * (i % ring) / ring, psi = 2.0 * kPi * (j % tube) / tube;
            const glm::dvec3 dPhi = surface(phi + h, psi) - surface(phi - h, psi);
            const glm::dvec3 dPsi = surface(phi, psi + h) - surface(phi, psi - h);
            m.positions.emplace_back(surface(phi, psi));
            m.normals.emplace_back(glm::normalize(glm::cross(dPhi, dPsi)));  // outward
            m.uvs.emplace_back(double(i) / ring, double(j) / tube);
        }
    addGridTriangles(m, 0, ring, tube);
    return m;
}

Mesh builtinMesh(const std::string& name) {
    if (name == "sphere") return builtinSphere();
    if (name == "plane") return builtinPlane();
    if (name == "default") return builtinDefault();
    std::string known;
    for (const std::string& n : builtinNames()) known += (known.empty() ? "" : ", ") + n;
    fail("mesh 'builtin:", name, "': no such built-in mesh (known: ", known, ")");
}

std::vector<std::string> builtinNames() {
    return {"sphere", "plane", "default"};
}

}  // namespace tsis
