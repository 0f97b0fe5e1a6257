#include "mesh/weld.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace tsis
