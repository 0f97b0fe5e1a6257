#include "mesh/weld.h"

#include <gtest/gtest.h>

#include <utility>

#include "mesh/builtin.h"

namespace tsis {
namespace {

// Two triangles of a unit square as a soup (each its own corners) sharing
// the diagonal from (1,0,0) to (0,1,0), one copy off by less than the
// tolerance (1e-6 of the box diagonal √2).
TEST(Weld, JoinsCopiesWithinTheTolerance) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1.0000001f, 0}};
    m.triangles = {{0, 1, 2}, {3, 4, 5}};
    EXPECT_EQ(weldPositions(m), (std::vector<uint32_t>{0, 1, 2, 1, 4, 2}));
    EXPECT_EQ(boundaryEdges(m), 4u);
    m.positions[5] = {0, 1.0001f, 0};  // beyond the tolerance: its own point
    EXPECT_EQ(weldPositions(m)[5], 5u);
    EXPECT_EQ(boundaryEdges(m), 6u);
}

TEST(Weld, SeamsDoNotOpenAClosedSurface) {
    // The sphere's date line is duplicated (not bit for bit) and its poles are
    // one vertex a slice; the torus' seams repeat angle 0.
    EXPECT_EQ(boundaryEdges(builtinSphere()), 0u);
    EXPECT_EQ(boundaryEdges(builtinDefault()), 0u);
    EXPECT_EQ(boundaryEdges(builtinPlane()), 4u * 32u);
}

// Closed and outward: a tetrahedron and a cube from bit-identical copies of
// their corners (a seam); not when a face is missing, when the winding is
// inward, or when one of two parts is inward even though the sum is outward.
TEST(Weld, ClosedOutwardNeedsEveryPartClosedAndWoundOut) {
    Mesh tetra;
    tetra.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
    tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    EXPECT_TRUE(closedOutward(tetra));
    Mesh seam = tetra;  // the last face from copies of its corners
    seam.positions.insert(seam.positions.end(), {{2, 0, 0}, {0, 2, 0}, {0, 0, 2}});
    seam.triangles[3] = {4, 5, 6};
    seam.triangles.push_back({0, 0, 1});  // a sliver on one point: ignored
    EXPECT_TRUE(closedOutward(seam));
    Mesh open = tetra;
    open.triangles.pop_back();
    EXPECT_FALSE(closedOutward(open));
    Mesh inward = tetra;
    for (glm::uvec3& t : inward.triangles) std::swap(t.y, t.z);
    EXPECT_FALSE(closedOutward(inward));
    // A big outward tetrahedron and a small inward one beside it.
    Mesh two = tetra;
    for (glm::vec3& p : two.positions) p *= 5.0f;
    for (const glm::vec3& p : inward.positions) two.positions.push_back(p + glm::vec3(20, 0, 0));
    for (const glm::uvec3& t : inward.triangles) two.triangles.push_back(t + 4u);
    EXPECT_FALSE(closedOutward(two));
    EXPECT_TRUE(closedOutward(builtinDefault()));
    EXPECT_FALSE(closedOutward(builtinPlane()));
}

}  // namespace
}  // namespace tsis
