#include "mesh/lod.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "mesh/builtin.h"

namespace tsis {
namespace {

Mesh sphere10() {
    Mesh m = builtinSphere();
    normalizeMesh(m, 10.0);
    return m;
}

// Cells far smaller than the triangles: every triangle stays, every vertex
// where it was (the seam's copies of a point merge, which a depth pass
// cannot tell).
TEST(MeshLod, FineCellsKeepTheMesh) {
    const Mesh m = sphere10();
    const MeshLod lod = clusterLod(m, 1e-4f);
    EXPECT_EQ(lod.mesh.triangles.size(), m.triangles.size());
    EXPECT_LE(lod.deviationMm, 1e-4f * std::sqrt(3.0f));
    EXPECT_LE(lod.mesh.positions.size(), m.positions.size());
}

// A budget of triangles gives about that many, each point of the copy within
// the deviation of the sphere, the deviation within a cell's diagonal.
TEST(MeshLod, SphereKeepsItsShapeWithinTheDeviation) {
    const Mesh m = sphere10();
    double radius = 0;
    for (const glm::vec3& p : m.positions) radius += glm::length(p);
    radius /= double(m.positions.size());
    for (size_t budget : {2000u, 8000u}) {
        SCOPED_TRACE(budget);
        const float cell = lodCellForBudget(m, budget);
        const MeshLod lod = clusterLod(m, cell);
        EXPECT_GT(lod.mesh.triangles.size(), budget / 2);
        EXPECT_LT(lod.mesh.triangles.size(), budget * 2);
        EXPECT_GT(lod.deviationMm, 0.0f);
        EXPECT_LE(lod.deviationMm, cell * std::sqrt(3.0f));
        for (const glm::vec3& p : lod.mesh.positions)
            EXPECT_NEAR(glm::length(p), radius, lod.deviationMm);
        for (const glm::uvec3& t : lod.mesh.triangles)
            EXPECT_TRUE(t.x != t.y && t.y != t.z && t.x != t.z);
    }
}

// A triangle inside one cell vanishes; two faces on the same three cells
// leave one; winding is kept.
TEST(MeshLod, DropsCollapsedAndRepeatedTriangles) {
    Mesh m;
    m.positions = {{0.1f, 0.1f, 0.1f}, {5.1f, 0.1f, 0.1f}, {0.1f, 5.1f, 0.1f},
                   {0.2f, 0.2f, 0.1f}, {0.3f, 0.1f, 0.1f}, {5.2f, 0.2f, 0.1f}};
    m.triangles = {{0, 1, 2}, {0, 3, 4}, {4, 5, 2}};
    const MeshLod lod = clusterLod(m, 1.0f);
    ASSERT_EQ(lod.mesh.triangles.size(), 1u);
    const glm::uvec3 t = lod.mesh.triangles[0];
    const glm::vec3 n = glm::cross(lod.mesh.positions[t.y] - lod.mesh.positions[t.x],
                                   lod.mesh.positions[t.z] - lod.mesh.positions[t.x]);
    EXPECT_GT(n.z, 0.0f);
    EXPECT_EQ(lod.mesh.positions.size(), 3u);
    EXPECT_NEAR(lod.deviationMm, glm::distance(glm::vec3(0.2f, 0.133333f, 0.1f), m.positions[0]),
                1e-5f);
}

}  // namespace
}  // namespace tsis
