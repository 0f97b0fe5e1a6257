#include "mesh/draw_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <glm/geometric.hpp>
#include <numeric>
#include <random>
#include <vector>

#include "mesh/builtin.h"

namespace tsis {
namespace {

// The sphere with its vertices and triangles listed in random order, as a
// scan or a subdivision lists them far from their neighbours.
Mesh shuffledSphere() {
    Mesh m = builtinSphere();
    std::mt19937 rng(7);
    std::vector<uint32_t> perm(m.positions.size());
    std::iota(perm.begin(), perm.end(), 0u);
    std::shuffle(perm.begin(), perm.end(), rng);
    std::vector<glm::vec3> positions(m.positions.size());
    for (size_t v = 0; v < perm.size(); ++v) positions[perm[v]] = m.positions[v];
    m.positions = positions;
    for (glm::uvec3& t : m.triangles) t = {perm[t.x], perm[t.y], perm[t.z]};
    std::shuffle(m.triangles.begin(), m.triangles.end(), rng);
    m.normals.clear();
    m.uvs.clear();
    return m;
}

glm::vec3 centroid(const std::vector<glm::vec3>& p, const glm::uvec3& t) {
    return (p[t.x] + p[t.y] + p[t.z]) / 3.0f;
}

// Mean distance between one triangle's centroid and the next's.
double meanStep(const std::vector<glm::vec3>& p, const std::vector<glm::uvec3>& triangles) {
    double sum = 0;
    for (size_t i = 1; i < triangles.size(); ++i)
        sum += glm::distance(centroid(p, triangles[i - 1]), centroid(p, triangles[i]));
    return sum / double(triangles.size() - 1);
}

TEST(DrawOrder, EveryTriangleOnceWithVerticesNumberedByFirstUse) {
    Mesh m = shuffledSphere();
    m.positions.push_back(glm::vec3(100.0f));  // used by no triangle
    const DrawOrder order = coherentDrawOrder(m);
    ASSERT_EQ(order.triangles.size(), m.triangles.size());
    EXPECT_EQ(order.vertexOf.size(), m.positions.size() - 1);

    auto corners = [](const std::vector<glm::uvec3>& ts, auto vertex) {
        std::vector<std::array<uint32_t, 3>> out;
        out.reserve(ts.size());
        for (const glm::uvec3& t : ts) out.push_back({vertex(t.x), vertex(t.y), vertex(t.z)});
        std::sort(out.begin(), out.end());
        return out;
    };
    EXPECT_EQ(corners(order.triangles, [&](uint32_t v) { return order.vertexOf.at(v); }),
              corners(m.triangles, [](uint32_t v) { return v; }));

    uint32_t next = 0;
    for (const glm::uvec3& t : order.triangles)
        for (int k = 0; k < 3; ++k) {
            EXPECT_LE(t[k], next);
            if (t[k] == next) ++next;
        }
}

// Consecutive triangles are neighbours: a step between centroids of about an
// edge, where the shuffled list jumps across the sphere.
TEST(DrawOrder, NearbyTrianglesFollowEachOther) {
    const Mesh m = shuffledSphere();
    const DrawOrder order = coherentDrawOrder(m);
    std::vector<glm::vec3> p;
    for (uint32_t v : order.vertexOf) p.push_back(m.positions[v]);
    const glm::uvec3 t = m.triangles[0];
    const double edge = glm::distance(m.positions[t.x], m.positions[t.y]);
    const double shuffled = meanStep(m.positions, m.triangles);
    const double ordered = meanStep(p, order.triangles);
    EXPECT_GT(shuffled, 20 * edge);
    EXPECT_LT(ordered, 3 * edge);
}

TEST(DrawOrder, EmptyMeshGivesNothing) {
    const DrawOrder order = coherentDrawOrder(Mesh{});
    EXPECT_TRUE(order.triangles.empty());
    EXPECT_TRUE(order.vertexOf.empty());
}

}  // namespace
}  // namespace tsis
