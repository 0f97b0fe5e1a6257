#include "mesh/builtin.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "mesh/repair.h"
#include "mesh/uv_check.h"
#include "support/error_of.h"

namespace tsis {
namespace {

using ::testing::HasSubstr;

glm::dvec3 faceNormal(const Mesh& m, size_t t) {
    const glm::dvec3 a(m.positions[m.triangles[t].x]), b(m.positions[m.triangles[t].y]),
        c(m.positions[m.triangles[t].z]);
    return glm::cross(b - a, c - a);
}

// Every face agrees with its vertices' normals, which are unit length, and
// the enclosed volume (divergence theorem) is positive for a closed shape.
void expectOutward(const Mesh& m, bool closed) {
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (const glm::vec3& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0, 1e-5);
    size_t disagree = 0;
    double volume = 0.0;
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        const glm::dvec3 f = faceNormal(m, t);
        for (int k = 0; k < 3; ++k)
            disagree += glm::dot(f, glm::dvec3(m.normals[m.triangles[t][k]])) <= 0.0;
        volume += glm::dot(glm::dvec3(m.positions[m.triangles[t].x]), f) / 6.0;
    }
    EXPECT_EQ(disagree, 0u) << m.name;
    if (closed) {
        EXPECT_GT(volume, 0.0) << m.name;
    }
}

void expectNoRepairs(Mesh m) {
    testing::internal::CaptureStderr();
    const RepairReport r = repairMesh(m);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << m.name;
    EXPECT_EQ(r.degenerateTriangles + r.unreferencedVertices + r.nonManifoldEdges, 0u);
}

TEST(Builtin, SphereCountsUVsAndWinding) {
    const Mesh m = builtinSphere();
    EXPECT_EQ(m.name, "builtin:sphere");
    EXPECT_EQ(m.triangles.size(), 28560u);
    ASSERT_EQ(m.uvs.size(), m.positions.size());
    for (const glm::vec2& uv : m.uvs) {
        EXPECT_GE(std::min(uv.x, uv.y), 0.0f);
        EXPECT_LE(std::max(uv.x, uv.y), 1.0f);
    }
    const UVCheck c = checkUVs(m);
    EXPECT_TRUE(c.ok) << c.problem;
    expectOutward(m, true);
    expectNoRepairs(m);
    for (const glm::vec3& p : m.positions) EXPECT_NEAR(glm::length(p), 1.0, 1e-6);
    // A pole vertex per slice, centred over it in u.
    size_t poles = 0;
    for (size_t i = 0; i < m.positions.size(); ++i) {
        if (std::abs(m.positions[i].y) != 1.0f) continue;
        ++poles;
        EXPECT_EQ(m.uvs[i].y, m.positions[i].y > 0 ? 0.0f : 1.0f);
        const double slot = m.uvs[i].x * 120.0 - 0.5;
        EXPECT_NEAR(slot, std::round(slot), 1e-4) << i;
    }
    EXPECT_EQ(poles, 240u);
    // Equal-area UVs: the UV atlas holds the whole surface.
    double uvArea = 0;
    for (size_t t = 0; t < m.triangles.size(); ++t) uvArea += m.triangleUVArea(t);
    EXPECT_NEAR(m.surfaceArea() / uvArea, 4 * M_PI, 0.01 * 4 * M_PI);
}

TEST(Builtin, SphereAreaRatioNearlyConstantAwayFromPoles) {
    const Mesh m = builtinSphere();
    // Between 30° and 150° from the pole. Each quad is a trapezoid in 3D and
    // a rectangle in UV, so its two triangles differ by ~Δθ·cot θ; the quad
    // as a whole keeps the ratio to a fraction of a percent.
    double lo = 1e9, hi = 0, qlo = 1e9, qhi = 0;
    for (size_t t = 0; t + 1 < m.triangles.size(); t += 1) {
        const glm::vec3 c = (m.positions[m.triangles[t].x] + m.positions[m.triangles[t].y] +
                             m.positions[m.triangles[t].z]) /
                            3.0f;
        if (std::abs(c.y) > std::cos(M_PI / 6)) continue;
        const double r = m.triangleArea(t) / m.triangleUVArea(t);
        lo = std::min(lo, r), hi = std::max(hi, r);
    }
    // Quads: the grid's triangles come in pairs after the 120 north-pole ones.
    for (size_t t = 120; t + 1 < m.triangles.size() - 120; t += 2) {
        const glm::vec3 c = m.positions[m.triangles[t].x];
        if (std::abs(c.y) > std::cos(M_PI / 6)) continue;
        const double r = (m.triangleArea(t) + m.triangleArea(t + 1)) /
                         (m.triangleUVArea(t) + m.triangleUVArea(t + 1));
        qlo = std::min(qlo, r), qhi = std::max(qhi, r);
    }
    std::printf("  sphere A3D/AUV, 30°..150°: triangles %.4f..%.4f, quads %.4f..%.4f (4π = %.4f)\n",
                lo, hi, qlo, qhi, 4 * M_PI);
    EXPECT_LT((hi - lo) / lo, 0.05);
    EXPECT_LT((qhi - qlo) / qlo, 0.002);
    EXPECT_NEAR(qlo, 4 * M_PI, 0.002 * 4 * M_PI);
}

TEST(Builtin, PlaneFacesUpWithExactUVs) {
    Mesh m = builtinPlane();
    EXPECT_EQ(m.triangles.size(), 2u * 32 * 32);
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        const glm::dvec3 n = glm::normalize(faceNormal(m, t));
        EXPECT_NEAR(n.y, 1.0, 1e-12);
    }
    for (size_t i = 0; i < m.positions.size(); ++i) {
        EXPECT_EQ(m.positions[i].y, 0.0f);
        EXPECT_EQ(m.uvs[i].x, m.positions[i].x + 0.5f);
        EXPECT_EQ(m.uvs[i].y, m.positions[i].z + 0.5f);
    }
    expectOutward(m, false);
    expectNoRepairs(m);
    const UVCheck c = checkUVs(m);
    EXPECT_TRUE(c.ok) << c.problem;
    normalizeMesh(m, 10.0);
    float xmax = -1e9f;
    for (const glm::vec3& p : m.positions) xmax = std::max(xmax, p.x);
    EXPECT_NEAR(2 * xmax, 10.0 / std::sqrt(2.0), 1e-4);  // diagonal = side·√2
}

TEST(Builtin, DefaultIsATaperedTorus) {
    const Mesh m = builtinDefault();
    EXPECT_GE(m.triangles.size(), 40000u);
    EXPECT_LE(m.triangles.size(), 60000u);
    const UVCheck c = checkUVs(m);
    EXPECT_TRUE(c.ok) << c.problem;
    expectOutward(m, true);
    expectNoRepairs(m);
    // Thin at the top, thick at the bottom: the tube's extent in z there.
    float topZ = 0, bottomZ = 0;
    for (const glm::vec3& p : m.positions) {
        if (std::abs(p.x) < 0.02f && p.y > 0) topZ = std::max(topZ, p.z);
        if (std::abs(p.x) < 0.02f && p.y < 0) bottomZ = std::max(bottomZ, p.z);
    }
    EXPECT_NEAR(topZ, 0.08, 0.01);
    EXPECT_NEAR(bottomZ, 0.42, 0.05);
}

TEST(Builtin, ByName) {
    for (const std::string& n : builtinNames()) EXPECT_EQ(builtinMesh(n).name, "builtin:" + n);
    EXPECT_THAT(test::errorOf([] { builtinMesh("teapot"); }, "builtin:teapot"),
                HasSubstr("known: sphere, plane, default"));
}

}  // namespace
}  // namespace tsis
