#include "mesh/mesh.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "mesh/builtin.h"
#include "support/error_of.h"

namespace tsis {
namespace {

using ::testing::HasSubstr;

// A tetrahedron with outward counter-clockwise faces, right-angled at the origin.
Mesh tetra() {
    Mesh m;
    m.name = "tetra";
    m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

TEST(Mesh, Areas) {
    Mesh m = tetra();
    EXPECT_DOUBLE_EQ(m.triangleArea(0), 2.0);
    EXPECT_NEAR(m.triangleArea(3), 0.5 * std::sqrt(3.0) * 8.0 / 2.0, 1e-12);  // side 2√2
    EXPECT_NEAR(m.surfaceArea(), 6.0 + 2.0 * std::sqrt(3.0), 1e-12);
    m.uvs = {{0, 0}, {1, 0}, {0, 1}, {0.5f, 0.5f}};
    EXPECT_DOUBLE_EQ(m.triangleUVArea(0), 0.5);  // clockwise in UV, area still positive
}

TEST(Mesh, EnclosedVolume) {
    EXPECT_NEAR(tetra().enclosedVolume(), 8.0 / 6.0, 1e-12);
    // Wherever the origin is: the sum is translation invariant when closed.
    Mesh moved = tetra();
    for (auto& p : moved.positions) p += glm::vec3(5, -3, 2);
    EXPECT_NEAR(moved.enclosedVolume(), 8.0 / 6.0, 1e-5);
}

TEST(Mesh, NormalizeGivesDiagonalAndCentre) {
    Mesh m = tetra();
    for (auto& p : m.positions) p = p * glm::vec3(3, 1, 0.5f) + glm::vec3(10, -4, 7);
    normalizeMesh(m, 25.0);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (auto& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    EXPECT_NEAR(glm::length(hi - lo), 25.0, 1e-4);
    EXPECT_NEAR(glm::length(0.5f * (lo + hi)), 0.0, 1e-5);
}

TEST(Mesh, NormalizeRefusesEmptyAndFlat) {
    Mesh m;
    m.name = "empty.off";
    EXPECT_THAT(test::errorOf([&] { normalizeMesh(m, 10); }, "empty.off"),
                HasSubstr("no vertices"));
    m.positions = {{1, 2, 3}, {1, 2, 3}};
    EXPECT_THAT(test::errorOf([&] { normalizeMesh(m, 10); }, "empty.off"), HasSubstr("zero"));
    Mesh t = tetra();
    EXPECT_THAT(test::errorOf([&] { normalizeMesh(t, -1); }), HasSubstr("positive"));
}

TEST(Mesh, EnsureNormalsAreaWeightedOutward) {
    Mesh m = tetra();
    ensureNormals(m, 180);  // smooth everywhere: one normal a vertex
    ASSERT_EQ(m.normals.size(), 4u);
    // Vertex 0 touches the three axis faces, equal areas: (−1,−1,−1)/√3.
    EXPECT_NEAR(m.normals[0].x, -1 / std::sqrt(3.0), 1e-6);
    EXPECT_NEAR(m.normals[0].y, -1 / std::sqrt(3.0), 1e-6);
    // Vertex 1: faces −z (area 2), −y (area 2), slanted (area 2√3, normal (1,1,1)/√3).
    const glm::dvec3 expect =
        glm::normalize(glm::dvec3(0, 0, -2) + glm::dvec3(0, -2, 0) +
                       2 * std::sqrt(3.0) * glm::dvec3(1, 1, 1) / std::sqrt(3.0));
    EXPECT_NEAR(m.normals[1].x, expect.x, 1e-6);
    EXPECT_NEAR(m.normals[1].y, expect.y, 1e-6);
    EXPECT_NEAR(m.normals[1].z, expect.z, 1e-6);
}

TEST(Mesh, EnsureNormalsKeepsValidFileNormals) {
    Mesh m = tetra();
    const float nan = std::nanf("");
    m.normals = {{0, 0, 5}, {0, 0, 0}, {nan, 0, 0}, {1, 0, 0}};
    ensureNormals(m, 180);
    EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));  // kept, normalised
    EXPECT_EQ(m.normals[3], glm::vec3(1, 0, 0));
    EXPECT_NEAR(glm::length(m.normals[1]), 1.0, 1e-6);  // replaced
    EXPECT_GT(m.normals[1].x, 0.0f);
    EXPECT_NEAR(glm::length(m.normals[2]), 1.0, 1e-6);
}

// A unit cube, 8 vertices, two outward counter-clockwise triangles a face.
Mesh cube() {
    Mesh m;
    m.name = "cube";
    for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    const glm::uvec4 quads[6] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                 {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const glm::uvec4& q : quads) {
        m.triangles.emplace_back(q.x, q.y, q.z);
        m.triangles.emplace_back(q.x, q.z, q.w);
    }
    return m;
}

glm::dvec3 faceNormal(const Mesh& m, size_t t) {
    const glm::uvec3 tri = m.triangles[t];
    const glm::dvec3 a(m.positions[tri.x]);
    return glm::normalize(
        glm::cross(glm::dvec3(m.positions[tri.y]) - a, glm::dvec3(m.positions[tri.z]) - a));
}

size_t distinctNormals(const Mesh& m) {
    std::vector<glm::vec3> seen;
    for (const glm::vec3& n : m.normals)
        if (std::find(seen.begin(), seen.end(), n) == seen.end()) seen.push_back(n);
    return seen.size();
}

TEST(Mesh, CubeSplitsAtTheCrease) {
    Mesh m = cube();
    const Mesh before = m;
    ensureNormals(m);                    // 60°: the cube's 90° edges are creases
    ASSERT_EQ(m.positions.size(), 24u);  // each corner once per face around it
    ASSERT_EQ(m.normals.size(), 24u);
    EXPECT_EQ(distinctNormals(m), 6u);
    ASSERT_EQ(m.triangles.size(), before.triangles.size());
    for (size_t t = 0; t < m.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            // Same corner positions, each with its own face's normal.
            EXPECT_EQ(m.positions[m.triangles[t][k]], before.positions[before.triangles[t][k]]);
            EXPECT_EQ(glm::dvec3(m.normals[m.triangles[t][k]]), faceNormal(m, t)) << t;
        }
    // The first 8 vertices stay where they were.
    for (size_t i = 0; i < 8; ++i) EXPECT_EQ(m.positions[i], before.positions[i]);
}

TEST(Mesh, CreaseZeroIsFlatAndOneEightyIsSmooth) {
    Mesh flat = cube();
    ensureNormals(flat, 0);  // a face's two triangles are exactly coplanar: one group
    EXPECT_EQ(flat.positions.size(), 24u);
    EXPECT_EQ(distinctNormals(flat), 6u);
    Mesh smooth = cube();
    ensureNormals(smooth, 180);
    ASSERT_EQ(smooth.positions.size(), 8u);
    // Corner 0 (the origin): equal areas of −x, −y, −z around it.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(smooth.normals[0][c], -1 / std::sqrt(3.0), 1e-6);
    // Just under a face angle: split; just over: joined.
    Mesh at89 = cube(), at91 = cube();
    ensureNormals(at89, 89.9);
    ensureNormals(at91, 90.1);
    EXPECT_EQ(at89.positions.size(), 24u);
    EXPECT_EQ(at91.positions.size(), 8u);
}

TEST(Mesh, CreaseSplitCopiesUVsAndKeepsFileNormals) {
    Mesh m = cube();
    for (const glm::vec3& p : m.positions) m.uvs.emplace_back(p.x, p.y);
    ensureNormals(m);
    ASSERT_EQ(m.uvs.size(), m.positions.size());
    for (size_t i = 8; i < m.positions.size(); ++i)
        EXPECT_EQ(m.uvs[i], glm::vec2(m.positions[i].x, m.positions[i].y));
    // A mesh with its own normals keeps them, unsplit.
    Mesh own = cube();
    own.normals.assign(8, glm::vec3(0, 0, 1));
    ensureNormals(own);
    EXPECT_EQ(own.positions.size(), 8u);
    EXPECT_EQ(own.normals, std::vector<glm::vec3>(8, glm::vec3(0, 0, 1)));
}

TEST(Mesh, CreaseSplitCopiesTexcoordsAndKeepsMaterials) {
    Mesh m = cube();
    for (const glm::vec3& p : m.positions) m.texcoords.emplace_back(p.x + 2 * p.y, p.z);
    for (size_t t = 0; t < m.triangles.size(); ++t) m.materialIds.push_back(uint32_t(t % 3));
    const std::vector<uint32_t> ids = m.materialIds;
    ensureNormals(m);
    EXPECT_EQ(m.positions.size(), 24u);  // split at every corner
    ASSERT_EQ(m.texcoords.size(), m.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i)
        EXPECT_EQ(m.texcoords[i],
                  glm::vec2(m.positions[i].x + 2 * m.positions[i].y, m.positions[i].z));
    EXPECT_EQ(m.materialIds, ids);  // triangles keep their order
}

TEST(Mesh, SmoothGroupsReachAcrossSeams) {
    // The cube as an OBJ with a UV per face corner: 24 vertices, a seam
    // between every two faces. Smooth everywhere, each corner's 3 copies get
    // the normal of the seamless cube's corner.
    const Mesh c = cube();
    Mesh m;
    for (size_t t = 0; t < c.triangles.size(); t += 2) {
        const uint32_t base = uint32_t(m.positions.size());
        const glm::uvec3 a = c.triangles[t], b = c.triangles[t + 1];
        for (uint32_t v : {a.x, a.y, a.z, b.z}) m.positions.push_back(c.positions[v]);
        m.triangles.emplace_back(base, base + 1, base + 2);
        m.triangles.emplace_back(base, base + 2, base + 3);
    }
    ensureNormals(m, 180);
    Mesh seamless = cube();
    ensureNormals(seamless, 180);
    ASSERT_EQ(m.positions.size(), 24u);
    for (size_t i = 0; i < 24; ++i) {
        const size_t j =
            size_t(std::find(seamless.positions.begin(), seamless.positions.end(), m.positions[i]) -
                   seamless.positions.begin());
        ASSERT_LT(j, 8u);
        EXPECT_NEAR(glm::length(m.normals[i] - seamless.normals[j]), 0.0, 1e-6) << i;
    }
    ensureNormals(m, 30);  // (normals now present: kept)
    EXPECT_EQ(m.positions.size(), 24u);
}

TEST(Mesh, SphereStaysSmooth) {
    Mesh m = builtinSphere();  // 3° between neighbouring faces; seams and poles welded
    const Mesh before = m;
    m.normals.clear();
    ensureNormals(m);
    EXPECT_EQ(m.positions.size(), before.positions.size());
    EXPECT_EQ(m.triangles, before.triangles);
    double worst = 1;
    for (size_t i = 0; i < m.positions.size(); ++i)
        worst = std::min(worst, glm::dot(glm::dvec3(m.normals[i]), glm::dvec3(before.normals[i])));
    EXPECT_GT(worst, 0.999);
}

TEST(Mesh, RotationMapsKnownPoints) {
    const glm::dvec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    // Right-handed, exact at quarter turns.
    EXPECT_EQ(meshRotation({90, 0, 0}, false) * y, z);
    EXPECT_EQ(meshRotation({0, 90, 0}, false) * z, x);
    EXPECT_EQ(meshRotation({0, 0, 90}, false) * x, y);
    EXPECT_EQ(meshRotation({0, 0, -270}, false) * x, y);
    // X first, then Y: y → z → x (Y first would leave y where it is, then → z).
    EXPECT_EQ(meshRotation({90, 90, 0}, false) * y, x);
    // Z-up: its +z becomes +y, its +y goes away from the default camera (−z).
    EXPECT_EQ(meshRotation({0, 0, 0}, true) * z, y);
    EXPECT_EQ(meshRotation({0, 0, 0}, true) * y, -z);
    EXPECT_EQ(meshRotation({0, 0, 0}, true) * x, x);
    // --mesh-up first, then --rotate.
    EXPECT_EQ(meshRotation({0, 0, 90}, true) * z, -x);
    const glm::dvec3 p = meshRotation({0, 30, 0}, false) * x;
    EXPECT_NEAR(p.x, std::sqrt(3.0) / 2, 1e-15);
    EXPECT_NEAR(p.z, -0.5, 1e-15);
}

TEST(Mesh, RotateMeshTurnsAboutTheBoxCentre) {
    Mesh m = tetra();  // box [0,2]³, centre (1,1,1)
    m.normals.assign(4, glm::vec3(0, 1, 0));
    rotateMesh(m, meshRotation({0, 0, 90}, false));
    EXPECT_EQ(m.positions[0], glm::vec3(2, 0, 0));  // (0,0,0) − c = (−1,−1,−1) → (1,−1,−1)
    EXPECT_EQ(m.positions[1], glm::vec3(2, 2, 0));
    EXPECT_EQ(m.normals[0], glm::vec3(-1, 0, 0));
    // The identity leaves every bit.
    Mesh odd = tetra();
    for (auto& q : odd.positions) q = q * 0.1f + glm::vec3(1e3f, 0.3f, -7);
    const Mesh copy = odd;
    rotateMesh(odd, meshRotation({0, 0, 0}, false));
    EXPECT_EQ(odd.positions, copy.positions);
}

}  // namespace
}  // namespace tsis
