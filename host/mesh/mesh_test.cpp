#include "mesh/mesh.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

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
    ensureNormals(m);
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
    ensureNormals(m);
    EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));  // kept, normalised
    EXPECT_EQ(m.normals[3], glm::vec3(1, 0, 0));
    EXPECT_NEAR(glm::length(m.normals[1]), 1.0, 1e-6);  // replaced
    EXPECT_GT(m.normals[1].x, 0.0f);
    EXPECT_NEAR(glm::length(m.normals[2]), 1.0, 1e-6);
}

}  // namespace
}  // namespace tsis
